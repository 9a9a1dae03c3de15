// SIGINT and SIGTERM in `wavepath render`: the one place the app handles signals. The first
// one asks the render to stop at the end of its pass (writing a checkpoint when it has one,
// nothing else); a second one ends the process at once, as the signal would.
#pragma once

namespace wp {

// Exit codes of an interrupted render: a checkpoint was written and the same command with
// --resume goes on (EX_TEMPFAIL: try again later), or nothing was written (128 + signal,
// as a shell reports a process the signal ended).
inline constexpr int kExitInterruptedResumable = 75;
int exitCodeInterrupted(int signal);

// Installs the handlers; call once before rendering.
void catchInterrupts();

// The signal (SIGINT or SIGTERM) received since catchInterrupts, or 0.
int interruptSignal();

// "SIGINT" or "SIGTERM".
const char* signalName(int signal);

}  // namespace wp
