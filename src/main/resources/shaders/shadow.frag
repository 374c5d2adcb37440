// Depth only: the colour is not written.
out vec4 fragColor;

void main() {
    fragColor = vec4(1.0);
}
