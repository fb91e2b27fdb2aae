// A missing semicolon at the end of line 4; glslang reports it at the next token (line 5).

void surface(inout MaterialInputs m, MaterialParams p) {
    float g = p.gain * 0.5
    m.roughness = g;
}
