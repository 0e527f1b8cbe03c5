// A layer's link check (CMakeLists.txt): linked with one layer's whole archive and the layers
// below it, so that a call from the layer to one above it fails to link. It runs nothing.
int main() { return 0; }
