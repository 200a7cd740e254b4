#pragma once
// Runs a helper program (no shell, so nothing in the arguments is ever interpreted).
#include <string>
#include <string_view>
#include <vector>

namespace hipr {

struct ProcessResult {
  int exit_code = -1;  // 127: the program could not be started
  std::string output;  // stdout + stderr
};

// Runs argv[0] (searched in PATH) with `input` on its standard input and waits for it.
ProcessResult run_process(const std::vector<std::string>& argv, std::string_view input);

}  // namespace hipr
