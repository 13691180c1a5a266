// Runs the inkshade binary with arguments and captures exit status, stdout and stderr.
#pragma once
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "support/temp_dir.hpp"

namespace inkshade::test {

struct CliResult {
    int status = -1;
    std::string out, err;
};

inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// `args` is passed to the shell as written (quote paths yourself); `env` prefixes it.
inline CliResult run_cli(const std::string& args, const std::string& env = "") {
    TempDir dir;
    std::string out = dir.file("stdout"), err = dir.file("stderr");
    std::string cmd = env + " " + INKSHADE_BIN + std::string(" ") + args + " >" + out + " 2>" + err + " </dev/null";
    int raw = std::system(cmd.c_str());
    CliResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

inline int line_count(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

}  // namespace inkshade::test
