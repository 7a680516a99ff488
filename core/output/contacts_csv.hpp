#pragma once
/// Writing the contact points of a run (`cairn run --contacts`): one row per contact point per
/// output sample, streamed to DIR/contacts.csv as the run goes.

#include <string>
#include <vector>

#include "backend/backend.hpp"
#include "output/buffered_file.hpp"
#include "run/sample_sink.hpp"

namespace cairn {

/// the header: t [s], block_a, block_b (names), x y z [m] (the point), nx ny nz [-] (unit normal
/// from block_b towards block_a), normal_force [N] (on block_a along the normal, > 0 pressing),
/// shear_x shear_y shear_z [N] (tangential force on block_a, world)
std::vector<std::string> contact_columns();

/// the rows of one sample's contact points (a block index of −1 is written "?")
std::string contact_rows(const Scene& scene, double t, const std::vector<ContactPoint>& points);

/// A sink that reads the backend's contact points at every sample (the run must record them:
/// RunOptions::record_contacts) and writes them to `path`; created at begin(), flushed, closed
/// and fsynced at end(). Throws std::runtime_error naming the file when it cannot be written.
class ContactsCsvFile : public SampleSink {
public:
    ContactsCsvFile(std::string path, const Backend& backend);
    void begin(const Scene& scene, const RunResult& run) override;
    void sample(const Sample& s) override;
    void end(const RunResult& run) override;

private:
    BufferedFile file_;
    const Backend& backend_;
    const Scene* scene_ = nullptr;
};

}  // namespace cairn
