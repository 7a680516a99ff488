#pragma once
/// Where a run's samples go as they are taken: a file written as the run goes (bounded memory), a
/// vector for the compare layer that analyses whole trajectories, or both.

#include <vector>

#include "backend/backend.hpp"

namespace cairn {

struct RunResult;

/// Receives the samples of one run, in order.
class SampleSink {
public:
    virtual ~SampleSink() = default;
    /// before the first sample; `run` has the time step, critical step and output interval
    virtual void begin(const Scene& scene, const RunResult& run) { (void)scene, (void)run; }
    /// one sample, t = 0 first
    virtual void sample(const Sample& s) = 0;
    /// after the last sample; `run` has the status, message and step count
    virtual void end(const RunResult& run) { (void)run; }
};

/// Keeps every sample in memory (memory grows with the run's length).
class CollectingSink : public SampleSink {
public:
    std::vector<Sample> samples;   ///< t = 0 first
    void sample(const Sample& s) override { samples.push_back(s); }
};

/// Drops every sample (a run timed for its wall time only).
class NullSink : public SampleSink {
public:
    void sample(const Sample&) override {}
};

/// Hands each call to several sinks in order.
class TeeSink : public SampleSink {
public:
    explicit TeeSink(std::vector<SampleSink*> sinks) : sinks_(std::move(sinks)) {}
    void begin(const Scene& scene, const RunResult& run) override {
        for (auto* s : sinks_) s->begin(scene, run);
    }
    void sample(const Sample& s) override {
        for (auto* k : sinks_) k->sample(s);
    }
    void end(const RunResult& run) override {
        for (auto* s : sinks_) s->end(run);
    }

private:
    std::vector<SampleSink*> sinks_;
};

}  // namespace cairn
