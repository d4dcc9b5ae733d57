// particle-sim: the headless runner. All logic lives in cli_app.cpp and its helpers.

#include <unistd.h>

#include <iostream>

#include "cli_app.hpp"

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv, argv + argc);
    return psb::cli::runCli(args, std::cout, std::cerr, ::isatty(STDERR_FILENO) == 1);
}
