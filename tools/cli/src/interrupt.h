// SIGINT and SIGTERM for ffx-dof apply: the handlers only set a flag; the work checks it between
// stages (a frame being written is finished, every other frame is abandoned), so no partial or
// temporary file is left, and the program ends with ExitCode::Interrupted (130) or Terminated (143).
#pragma once

#include <string>

namespace ffxdof::cli {

// Installs the handlers (idempotent).
void installInterruptHandlers();
// The signal received (SIGINT or SIGTERM), or 0.
int interruptSignal();
// Throws CliError(Interrupted or Terminated) when a signal was received: "interrupted by SIGINT; <what>".
void throwIfInterrupted(const std::string& what = "");

}  // namespace ffxdof::cli
