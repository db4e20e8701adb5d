#pragma once
#include <volume_model/LoadProgress.h>

#include <chrono>
#include <string>

namespace volren::app {

/// Progress on stderr once the task has taken over 0.5 s (VOLREN_PROGRESS_DELAY=seconds
/// overrides): on a terminal a one-line bar ("loading NAME [####    ] 42%") redrawn and cleared
/// at the end; elsewhere (logs, pipes) a start line, a line per 10 % for tasks over 3 s and an
/// end line with the time taken. Hand callback() to the reader or writer (withLoadProgress); it
/// never cancels.
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
    std::string _label;     ///< "loading NAME"
    bool _terminal = true;  ///< stderr is a terminal
    double _delay = 0.5;    ///< seconds before progress shows
    int _shown = -1;        ///< percent last shown; -1 until the task has taken _delay
    LoadProgress _callback;
};

}  // namespace volren::app
