#include "pipeline/progress.h"

#include "pipeline/workers.h"

#include <cstdio>

namespace impact::pipeline {

progress::progress(bool enabled) : enabled_(enabled)
{
    if (enabled_)
        painter_ = std::thread([this] { show(); });
}

progress::~progress()
{
    if (!enabled_)
        return;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    painter_.join();
}

void progress::say(const std::string& task, const std::string& what)
{
    if (!enabled_)
        return;
    const std::lock_guard<std::mutex> lock(mutex_);
    auto [at, added] = tasks_.try_emplace(task, running{std::chrono::steady_clock::now(), what});
    if (!added)
        at->second.what = what;
}

void progress::done(const std::string& task)
{
    if (!enabled_)
        return;
    const std::lock_guard<std::mutex> lock(mutex_);
    tasks_.erase(task);
}

void progress::show()
{
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
        wake_.wait_for(lock, std::chrono::milliseconds(200));
        // No fork() while this thread allocates and prints (workers.h).
        const std::lock_guard<std::mutex> still(fork_lock());
        const auto second_ago = std::chrono::steady_clock::now() - std::chrono::seconds(1);
        std::string line;
        for (const auto& [task, r] : tasks_)
            if (r.since < second_ago)
                line += (line.empty() ? "impact: " : "; ") + r.what;
        if (line.size() > 150)
            line = line.substr(0, 147) + "...";
        if (stop_)
            line.clear();
        if (line != shown_) {
            // Back to the start of the line, the new text, the rest of the old one erased.
            std::fprintf(stderr, "\r%s\033[K", line.c_str());
            std::fflush(stderr);
            shown_ = line;
        }
    }
}

} // namespace impact::pipeline
