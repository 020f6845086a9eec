// cli/session.hpp
// Provides:   run_session(), the interactive mode of `qm-atms SCENE.def -i`: queries typed on `in`
//             (situation, freedom, motions, kinematic, why, given, whatif, with, json, help, quit;
//             `help` lists them) answered against the loaded analysis without reloading anything,
//             about situation `situation` until `situation N` (the scene's --situation).
//             On a terminal (`in` is standard input on a tty) lines are read with libedit: a
//             prompt, line editing and history (cli/line_editor.hpp).
// Errors:     a bad query is reported on err (located as `why:1:COL: error: ...`), a command given
//             the wrong arguments with its usage, an unknown one with "did you mean"; the session
//             goes on; qm::InternalError propagates to main (exit 1).
#pragma once
#include "analysis/fwd.hpp"
#include <cstddef>
#include <istream>
#include <ostream>

namespace qm::cli {
// Pre: 1 <= situation <= the analysis' situations.
void run_session(analysis::Analysis& analysis, bool json, std::size_t situation, std::istream& in, std::ostream& out, std::ostream& err);
}
