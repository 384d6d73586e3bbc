// Placeholder entry point; the scenario/CLI work replaces it with the full command set.
#include <cstdio>

int main() {
  std::puts("impactbench: no commands yet");
  return 0;
}
