// Exit codes of the ffx-dof command line and the one exception type that carries them.
//
// Every failure ends the program with exactly one line on stderr ("ffx-dof: error: ...") and one
// of these codes. docs/cli.md and `ffx-dof --help` list the same table; exitCodeTable() is the
// text both are made from.
#pragma once

#include "ffx_dof_imageio.h"

#include <stdexcept>
#include <string>

namespace ffxdof::cli {

enum class ExitCode : int {
    Success = 0,
    Usage = 1,      // unknown option, missing or malformed argument, conflicting options, unknown output extension
    InputFile = 2,  // an input file is missing, unreadable, corrupt, or lacks the expected channels
    InvalidValue =
        3,            // impossible lens or projection values, bad depths, mismatched resolutions, out-of-range settings
    Device = 4,       // no usable Vulkan device, or the effect / Vulkan reported an error
    OutputWrite = 5,  // an output file or directory could not be written
    Internal = 6,     // a bug: an unexpected exception (please report it)
    Interrupted = 130,  // SIGINT (as shells report it: 128 + 2); no partial output is left
    Terminated = 143,   // SIGTERM (128 + 15); no partial output is left
};

// The table printed by --help and written in docs/cli.md.
const char* exitCodeTable();

class CliError : public std::runtime_error {
public:
    CliError(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
    ExitCode code() const { return code_; }

private:
    ExitCode code_;
};

// Runs an input-reading call, turning the image library's errors into exit code InputFile.
template <typename Read>
auto readInput(Read read) {
    try {
        return read();
    } catch (const io::IoError& error) {
        throw CliError(ExitCode::InputFile, error.what());
    }
}

}  // namespace ffxdof::cli
