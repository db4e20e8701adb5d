#pragma once
#include <volume_model/LoadProgress.h>

#include <chrono>
#include <string>

namespace volren::app {

/// A one-line progress bar on stderr ("loading NAME [####    ] 42%"), drawn once the task has
/// taken over 0.5 s and cleared when the bar goes out of scope. Hand callback() to the reader
/// or writer (withLoadProgress); it never cancels.
class ProgressBar
{
public:
    ProgressBar(const std::string& verb, const std::string& name);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    const LoadProgress& callback() const { return _callback; }  ///< reports a fraction done

private:
    std::chrono::steady_clock::time_point _start;
    int _shown = -1;  ///< percent last drawn; -1 until the task has taken 0.5 s
    LoadProgress _callback;
};

}  // namespace volren::app
