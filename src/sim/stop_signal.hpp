#pragma once
// SIGINT / SIGTERM during a run: the handler only records the signal; the run loop notices it
// after the current step, writes a checkpoint, flushes its outputs and stops cleanly.
namespace mpdem {

void install_stop_handlers();  // idempotent
int stop_signal();             // the signal received, or 0
void clear_stop_signal();      // for tests

}  // namespace mpdem
