#pragma once
// A command line that CLI11 refused, said in the project's words. CLI11's own text for an
// unknown option lists the leftover arguments in reverse ("The following arguments were not
// expected: 3 --seed" for `--sed 3`) and names nothing the user could have meant.

#include <string>

#include <CLI/CLI.hpp>

namespace psb {

/// One line, without the program's prefix or a pointer to --help: for an unknown option
/// "unknown option '--sed' (did you mean '--seed'?)" (the nearest option, when one is close);
/// for a stray argument "unexpected argument 'b.json' (SCENE is 'a.json'; options start with
/// '-')"; for any other error CLI11's message (but a required option missing because it was
/// misspelt is reported as the unknown option). `app` is the parser that threw `error`.
[[nodiscard]] std::string parseErrorMessage(const CLI::App& app, const CLI::ParseError& error);

}  // namespace psb
