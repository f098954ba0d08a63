#pragma once
#include <chrono>
#include <mutex>
#include <string>

namespace darkroom::cli {

// A one-line progress bar with ETA on stderr, drawn only when stderr is a
// terminal (so logs and pipes stay clean). Thread-safe; redraws at most 10x/s.
class ProgressBar {
public:
    explicit ProgressBar(std::string label, bool enabled);
    ~ProgressBar();
    void update(double fraction, const std::string& detail = {});
    void finish();

private:
    void draw(double fraction, const std::string& detail);
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace darkroom::cli
