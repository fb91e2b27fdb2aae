// A user's source file: no matbricks command may delete or change it.
int main() { return 0; }
