// Shadow-map pass for meshes: depth only, so the fragment stage does nothing and early depth testing stays on.
void main() {
}
