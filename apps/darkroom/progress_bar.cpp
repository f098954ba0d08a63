#include "progress_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace darkroom::cli {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled), start_(std::chrono::steady_clock::now()), last_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(double fraction, const std::string& detail) {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && fraction < 1.0 && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    draw(std::clamp(fraction, 0.0, 1.0), detail);
}

void ProgressBar::draw(double f, const std::string& detail) {
    const int width = 30;
    const int filled = int(std::lround(f * width));
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string eta = "--:--";
    if (f > 0.01) {
        const int s = int(std::lround(elapsed * (1.0 - f) / f));
        char buf[32];
        std::snprintf(buf, sizeof buf, "%02d:%02d", s / 60, s % 60);
        eta = buf;
    }
    std::string shown = detail.size() > 30 ? detail.substr(0, 29) + "~" : detail;
    std::fprintf(stderr, "\r\033[K%s [%s%s] %3d%% ETA %s %s", label_.c_str(), std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), int(f * 100), eta.c_str(), shown.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::finish() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (enabled_ && drawn_) {
        std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
        drawn_ = false;
    }
}

}  // namespace darkroom::cli
