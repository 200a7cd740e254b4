#pragma once
// Errors that reach the user. InputError is the user's fault (bad file, bad flag) and maps to
// exit code 2; anything else is ours (exit code 1). Both carry one printable line.
#include <stdexcept>
#include <string>

namespace hipr {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InternalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;
// `hipr compare`: the images differ (as cmp and diff answer; the same code as an internal error).
constexpr int kExitDifferent = 1;

}  // namespace hipr
