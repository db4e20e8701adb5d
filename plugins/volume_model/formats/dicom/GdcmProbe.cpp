#include "GdcmProbe.h"

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <fcntl.h>
#include <cstring>
#include <sys/wait.h>
#include <unistd.h>

namespace volren::dicom {

std::string probeInChild(const std::vector<std::string>& files, const std::function<void(const std::string&)>& step)
{
    int channel[2];
    if (files.empty() || ::pipe(channel) != 0) return "";
    const pid_t child = ::fork();
    if (child < 0) {
        ::close(channel[0]);
        ::close(channel[1]);
        return "";
    }
    if (child == 0) {  // the child: report the index of each file before touching it
        ::close(channel[0]);
        // Default deaths: handlers inherited from the parent (a fuzzer's or a sanitizer's crash
        // reporting) must not turn the child's abort into an exit the parent cannot tell apart.
        for (int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, SIG_DFL);
        const int quiet = ::open("/dev/null", O_WRONLY);  // GDCM's messages come again in the real run
        if (quiet >= 0) ::dup2(quiet, 2);
        for (std::uint32_t i = 0; i < files.size(); ++i) {
            if (::write(channel[1], &i, sizeof i) != sizeof i) ::_exit(2);
            try {
                step(files[i]);
            } catch (...) {
                // Exceptions are ordinary errors; the real run reports them.
            }
        }
        ::_exit(0);
    }
    ::close(channel[1]);
    std::uint32_t last = 0, index = 0;
    bool started = false;
    while (::read(channel[0], &index, sizeof index) == sizeof index) last = index, started = true;
    ::close(channel[0]);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {}
    if (WIFSIGNALED(status) && started)
        return files[last] + ": GDCM aborted reading it (" + std::string(::strsignal(WTERMSIG(status))) +
               "): a malformed DICOM file";
    return "";
}

}  // namespace volren::dicom
