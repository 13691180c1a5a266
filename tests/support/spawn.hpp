// Starts the inkshade binary under test (INKSHADE_BIN, a compile definition of the test
// binaries) as a child process without a shell, so a signal sent to the returned pid reaches
// inkshade itself: for the tests that interrupt or kill a batch midway. stdin is /dev/null,
// stdout and stderr go to the given files. Test support only (POSIX).
#pragma once
#include <fcntl.h>
#include <sys/types.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace inkshade::test {

inline pid_t spawn(const std::vector<std::string>& args, const std::string& stdout_path,
                   const std::string& stderr_path) {
    const pid_t pid = fork();
    if (pid == 0) {
        const int in = open("/dev/null", O_RDONLY);
        const int out = open(stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = open(stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(in, 0);
        dup2(out, 1);
        dup2(err, 2);
        std::vector<char*> argv{const_cast<char*>(INKSHADE_BIN)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(INKSHADE_BIN, argv.data());
        _exit(127);
    }
    return pid;
}

}  // namespace inkshade::test
