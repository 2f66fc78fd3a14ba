// Placeholder entry point; the subcommands land in apps/.
#include <cstdio>

int main() {
  std::fprintf(stderr, "usage: tpopt <generate|evaluate|smooth> [flags]\n");
  return 2;
}
