#include "progress_line.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cairn {

std::string progress_text(const std::string& label, double fraction, double duration, double dt, double elapsed) {
    char buf[160];
    const double sim = fraction * duration;
    const double rate = dt > 0.0 && elapsed > 0.0 ? sim / dt / elapsed : 0.0;
    const double left = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    std::snprintf(buf, sizeof buf, ": t = %.3g / %.3g s (%3.0f %%), %.3g steps/s, %.0f s left", sim, duration,
                  100.0 * fraction, rate, std::ceil(left));
    return label + buf;
}

ProgressLine::ProgressLine(std::string label, double duration) : label_(std::move(label)), duration_(duration) {
    start_ = std::chrono::steady_clock::now();
}

void ProgressLine::begin(const Scene&, const RunResult& run) {
    dt_ = run.dt;
    start_ = std::chrono::steady_clock::now();
}

ProgressFn ProgressLine::function() {
    return [this](double f) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const std::string text = progress_text(label_, f, duration_, dt_, elapsed);
        // pad over a longer previous line
        std::fprintf(stderr, "\r%s%*s", text.c_str(), int(width_ > text.size() ? width_ - text.size() : 0), "");
        std::fflush(stderr);
        width_ = std::max(width_, text.size());
    };
}

void ProgressLine::clear() const {
    if (width_ == 0) return;
    std::fprintf(stderr, "\r%*s\r", int(width_), "");
    std::fflush(stderr);
}

PoolProgress::PoolProgress(std::string label, size_t runs, double duration)
    : label_(std::move(label)), duration_(duration), done_(runs, 0.0), start_(std::chrono::steady_clock::now()) {}

void PoolProgress::update(size_t run, double fraction) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (run >= done_.size()) return;
    done_[run] = std::max(done_[run], std::min(1.0, fraction));
    double sum = 0.0;
    size_t ended = 0;
    for (double f : done_) {
        sum += f;
        ended += f >= 1.0;
    }
    const double f = sum / double(done_.size());
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    char buf[200];
    std::snprintf(buf, sizeof buf, ": %zu of %zu runs done, %.3g of %.3g s simulated (%3.0f %%), %.0f s left", ended,
                  done_.size(), sum * duration_, double(done_.size()) * duration_, 100.0 * f,
                  f > 0.0 ? std::ceil(elapsed * (1.0 - f) / f) : 0.0);
    const std::string text = label_ + buf;
    std::fprintf(stderr, "\r%s%*s", text.c_str(), int(width_ > text.size() ? width_ - text.size() : 0), "");
    std::fflush(stderr);
    width_ = std::max(width_, text.size());
}

void PoolProgress::clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (width_ == 0) return;
    std::fprintf(stderr, "\r%*s\r", int(width_), "");
    std::fflush(stderr);
}

}  // namespace cairn
