#include <unistd.h>

#include <iostream>

#include "commands.hpp"

namespace cairn {

bool stderr_is_terminal() { return isatty(STDERR_FILENO) != 0; }

int interrupted_keeping(const std::string& what, const std::string& dir) {
    std::cerr << "interrupted: no new " << what << " written; " << dir << " keeps the previous one\n";
    return kExitInterrupted;
}

int run_command(RunJob job, bool quiet) {
    job.progress = !quiet && stderr_is_terminal();
    job.label = job.scene + " on " + job.backend;
    const JobOutcome o = execute_run(job);
    for (const std::string& w : o.warnings) std::cerr << w << "\n";
    switch (o.status) {
        case JobStatus::input_error:
        case JobStatus::refused:
            std::cerr << "error: " << o.message << "\n";
            return kExitBadInput;
        case JobStatus::unstable:
            std::cerr << "error: " << o.message << "\n"
                      << "partial trajectory kept in " << job.out_dir << "/trajectory.partial.csv\n";
            if (!quiet) std::cout << summary_line(o) << "\n";
            return kExitUnstable;
        case JobStatus::interrupted:
            std::cerr << "interrupted: " << o.message << "\n"
                      << "partial trajectory kept in " << job.out_dir << "/trajectory.partial.csv\n";
            return kExitInterrupted;
        case JobStatus::failed:   // not returned by execute_run (its failures propagate)
            std::cerr << "error: " << o.message << "\n";
            return kExitFailure;
        case JobStatus::completed:
            if (!quiet) std::cout << summary_line(o) << " -> " << job.out_dir << "\n";
            return kExitOk;
    }
    return kExitFailure;
}

}  // namespace cairn
