// host/app/printd/main.cpp: the printd daemon.
#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"printd: garment print daemon"};
  CLI11_PARSE(app, argc, argv);
  return 0;
}
