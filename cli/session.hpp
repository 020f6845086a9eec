// cli/session.hpp
// Provides:   run_session(), the interactive mode of `qm-atms SCENE.def -i`: queries typed on `in`
//             (situation, freedom, motions, why, given, whatif, json, help, quit; `help` lists them)
//             answered against the loaded analysis without reloading anything. A prompt is shown
//             only when `in` is standard input on a terminal.
// Errors:     a bad query is reported on err (located as `why:1:COL: error: ...`) and the session
//             goes on; qm::InternalError propagates to main (exit 1).
#pragma once
#include "analysis/fwd.hpp"
#include <istream>
#include <ostream>

namespace qm::cli {
void run_session(analysis::Analysis& analysis, bool json, std::istream& in, std::ostream& out, std::ostream& err);
}
