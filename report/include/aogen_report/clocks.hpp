// aogen_report/clocks.hpp — the GPU's SM clock while the report times, read with nvidia-smi.
//
// WHAT
//   A timing is only as good as the clock the GPU ran at: an NVIDIA GPU left idle between
//   runs sits at a fraction of its working clock. clock_monitor samples the SM clock
//   (`nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm`) on a thread of its own every
//   `period_ms` between start() and stop(), for the GPU whose name the Vulkan device's
//   contains ("NVIDIA H200" in "NVIDIA H200"), each reading with the host time it came at,
//   so a caller keeps the ones taken while it timed (not those of a warm-up). Where
//   nvidia-smi is missing or names no such GPU (lavapipe, another vendor), available() is
//   false and no sample is ever taken. It only reads: it never sets a clock or a power limit.
//
// USAGE
//     aogen_report::clock_monitor clocks(ctx.device_name());
//     clocks.start();
//     ... time something ...
//     clocks.stop();
//     std::vector<double> mhz = clocks.between(t0, t1);   // readings in [t0, t1]; none when not available()
//     clocks.timeline();                                  // every reading, with its time
//     clocks.max_mhz();                             // the GPU's maximum SM clock, 0 if unknown
#pragma once

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace aogen_report {

class clock_monitor {
public:
    explicit clock_monitor(std::string device_name, int period_ms = 100) : device_(std::move(device_name)), period_ms_(period_ms)
    {
        double sm = 0, max = 0;
        available_ = read(sm, max);
        max_mhz_ = available_ ? max : 0;
    }
    ~clock_monitor() { stop(); }
    clock_monitor(const clock_monitor&) = delete;
    clock_monitor& operator=(const clock_monitor&) = delete;

    bool available() const { return available_; }
    double max_mhz() const { return max_mhz_; }

    // One reading: when nvidia-smi answered (host clock, and ms since start()), SM MHz.
    struct sample {
        std::chrono::steady_clock::time_point at;
        double ms = 0, mhz = 0;
    };

    void start()
    {
        if (!available_ || running_) return;
        samples_.clear();
        running_ = true;
        const auto started = std::chrono::steady_clock::now();
        thread_ = std::thread([this, started] {
            while (running_) {
                double sm = 0, max = 0;
                if (read(sm, max)) {
                    const auto at = std::chrono::steady_clock::now();
                    const double ms = std::chrono::duration<double, std::milli>(at - started).count();
                    std::lock_guard<std::mutex> lock(mutex_);
                    samples_.push_back({at, ms, sm});
                }
                for (int waited = 0; running_ && waited < period_ms_; waited += 10) std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
        });
    }

    // Ends the sampling; timeline() has the readings.
    void stop()
    {
        if (!running_) return;
        running_ = false;
        thread_.join();
    }

    // The SM clocks (MHz) read between `from` and `to` in the last start()..stop().
    std::vector<double> between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) const
    {
        std::vector<double> mhz;
        for (const sample& s : timeline())
            if (s.at >= from && s.at <= to) mhz.push_back(s.mhz);
        return mhz;
    }

    // The readings of the last start()..stop(), in order.
    std::vector<sample> timeline() const
    {
        std::lock_guard<std::mutex> lock(mutex_);
        return samples_;
    }

private:
    // One reading of this device's SM clock and maximum SM clock; false if there is none.
    bool read(double& sm, double& max) const
    {
        FILE* pipe = popen("nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm --format=csv,noheader,nounits 2>/dev/null", "r");
        if (!pipe) return false;
        std::string text;
        char buffer[256];
        while (std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
        const int status = pclose(pipe);
        if (status != 0) return false;
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);) {
            // "NVIDIA H200, 1980, 1980"
            const size_t a = line.find(','), b = line.rfind(',');
            if (a == std::string::npos || a == b) continue;
            const std::string name = line.substr(0, a);
            if (name.empty() || device_.find(name) == std::string::npos) continue;
            try {
                sm = std::stod(line.substr(a + 1, b - a - 1));
                max = std::stod(line.substr(b + 1));
                return true;
            } catch (const std::exception&) {
                return false; // "[N/A]" and the like
            }
        }
        return false;
    }

    std::string device_;
    int period_ms_;
    bool available_ = false;
    double max_mhz_ = 0;
    std::atomic<bool> running_{false};
    std::thread thread_;
    mutable std::mutex mutex_;
    std::vector<sample> samples_;
};

} // namespace aogen_report
