// A progress line on the terminal for what takes more than a second.
//
// Stages say what they are doing (`say`), from any thread; nothing is printed for the
// first second of a task, so a quick run prints nothing. Only on a terminal, and not
// with --quiet: the caller decides (`enabled`). The line is rewritten in place on
// standard error and cleared when the task is done, so that what stays on the screen is
// what Impact printed anyway.
#pragma once

#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <string>
#include <thread>

namespace impact::pipeline {

class progress {
public:
    explicit progress(bool enabled);
    ~progress();
    progress(const progress&) = delete;
    progress& operator=(const progress&) = delete;

    /// `task` is running and doing `what` (e.g. "choosing kernel forms: 3 of 12 kernels").
    void say(const std::string& task, const std::string& what);
    /// `task` is finished.
    void done(const std::string& task);

private:
    void show();
    struct running {
        std::chrono::steady_clock::time_point since;
        std::string what;
    };
    bool enabled_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::map<std::string, running> tasks_;
    std::string shown_;
    std::thread painter_;
};

} // namespace impact::pipeline
