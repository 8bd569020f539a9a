// Trivial program of the link_<library> tests (tests/link/CMakeLists.txt): what is checked is that it links.
#include <cstdio>

int main() {
  std::printf("%s links as a whole archive with only the layers it declares\n", CONFORMA_LINKED_LIBRARY);
  return 0;
}
