// Errors that cross the library boundary. The CLI prints what() on one line
// prefixed by "inkshade: " and exits 2 for InputError, 1 for RuntimeError.
#pragma once
#include <stdexcept>
#include <string>

namespace inkshade {

// Bad input: unreadable/malformed file, bad option value. what() == "FILE: problem"
// when a file is involved, else just the problem.
class InputError : public std::runtime_error {
public:
    InputError(const std::string& file, const std::string& problem)
        : std::runtime_error(file.empty() ? problem : file + ": " + problem) {}
    explicit InputError(const std::string& problem) : std::runtime_error(problem) {}
};

// Failure while rendering or writing output (no GL, shader compile error, disk full).
class RuntimeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace inkshade
