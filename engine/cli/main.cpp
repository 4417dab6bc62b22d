// The washout program: one binary, one command per task (INTERFACE.md "Command line").
#include <cstdio>
#include <cstring>
#include <string>

#include "engine/cli/run_command.hpp"
#include "engine/cli/study_command.hpp"
#if __has_include("engine/cli/render_command.hpp")
#include "engine/cli/render_command.hpp"
#define WASHOUT_HAS_RENDER 1
#endif

namespace {

const char* kUsage =
    "washout " WASHOUT_VERSION
    " - stabilized ISPH for bridge-girder wash-out\n"
    "\n"
    "usage: washout run SCENE.lua [--out DIR] [--set NAME=VALUE ...] [--threads N] [--quiet]\n"
    "       washout render RUN.h5 [--out DIR] [--every K] [--width W --height H] [--color FIELD]\n"
    "       washout study SCENE.lua --vary NAME=V1,V2,... [--vary ...] [--repeat N] [--out DIR]\n"
    "                     [--set NAME=VALUE ...] [--threads N]\n"
    "                     (error against run time: DIR/study.csv and study.png)\n"
    "       washout --help | --version | COMMAND --help\n"
    "\n"
    "Documentation: README.md and docs/ in the source tree.\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "%s", kUsage);
    return 1;
  }
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::printf("%s", kUsage);
    return 0;
  }
  if (command == "--version") {
    std::printf("washout %s\n", WASHOUT_VERSION);
    return 0;
  }
  if (command == "run") return washout::cli::run_command(argc - 1, argv + 1);
  if (command == "study") return washout::cli::run_study_command(argc - 1, argv + 1);
#ifdef WASHOUT_HAS_RENDER
  if (command == "render") return washout::cli::run_render_command(argc - 1, argv + 1);
#endif
  std::fprintf(stderr, "washout: unknown command '%s'\n\n%s", command.c_str(), kUsage);
  return 1;
}
