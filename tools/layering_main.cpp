// Entry point of the layering-check executables (CMakeLists.txt, gmr_module): they link one
// library whole with only its declared dependencies, so an undeclared dependency fails the link.
int main() { return 0; }
