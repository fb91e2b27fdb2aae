// Exists, but lies outside the project directory of project/m.json.
void surface(inout MaterialInputs m, MaterialParams p) {}
