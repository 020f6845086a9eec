// tests/cli/progress_bar_test.cpp: the envisioner's progress line and the "how far it got" text of
// a limit's message (cli/progress_bar.hpp), from given counts and seconds; and a ProgressBar that
// does not draw adding up the chains it was told of.
#include "progress_bar.hpp"
#include <doctest/doctest.h>
#include <string>

using qm::cli::progress_line;
using qm::cli::run_so_far_text;
using ProgressPhase = qm::envision::Progress::Phase;

TEST_CASE("cli/progress_bar: the line shows what the phase has found and how many a second") {
    CHECK(progress_line({}, 3.0) == "place vocabularies");
    CHECK(progress_line({.phase = ProgressPhase::states, .chain = 1, .states = 12288}, 2.0) == "chain 1: 12288 states (6144 states/s)");
    CHECK(progress_line({.phase = ProgressPhase::states, .chain = 3, .states = 7}, 0.0) == "chain 3: 7 states (0 states/s)");
    CHECK(progress_line({.phase = ProgressPhase::transitions, .chain = 2, .states = 1378, .transitions = 950, .done = 600}, 0.5) ==
          "chain 2: 950 transitions (1900 transitions/s) [####      ] 600/1378 states");
    CHECK(progress_line({.phase = ProgressPhase::transitions, .chain = 1, .states = 3, .transitions = 4, .done = 3}, 4.0) ==
          "chain 1: 4 transitions (1 transitions/s) [##########] 3/3 states");
    CHECK(progress_line({.phase = ProgressPhase::transitions, .chain = 1}, 1.0) == "chain 1: 0 transitions (0 transitions/s) [          ] 0/0 states");
}

TEST_CASE("cli/progress_bar: how far a run got names the phase, the chain, the time and the counts over all chains") {
    CHECK(run_so_far_text({}, false, 0, 0, 0.04, "a.def") == "making the place vocabularies of a.def (after 0.0 s: 0 states and 0 transitions found)");
    CHECK(run_so_far_text({.phase = ProgressPhase::states, .chain = 2, .states = 310}, false, 1000, 1080, 3.14, "clock.def") ==
          "finding the states of chain 2 of clock.def (after 3.1 s: 1000 states and 1080 transitions found)");
    CHECK(run_so_far_text({.phase = ProgressPhase::transitions, .chain = 1, .states = 9}, false, 9, 5, 12.0, "b.def") ==
          "finding the transitions of chain 1 of b.def (after 12.0 s: 9 states and 5 transitions found)");
    CHECK(run_so_far_text({.phase = ProgressPhase::transitions, .chain = 1, .states = 9}, true, 9, 12, 12.0, "b.def") ==
          "answering from the envisionment of b.def (after 12.0 s: 9 states and 12 transitions found)");
}

TEST_CASE("cli/progress_bar: the counts of finished chains are added to the chain at work") {
    qm::cli::ProgressBar bar(false);
    bar({});
    bar({.phase = ProgressPhase::states, .chain = 1});
    bar({.phase = ProgressPhase::states, .chain = 1, .states = 690});
    bar({.phase = ProgressPhase::transitions, .chain = 1, .states = 690, .transitions = 500, .done = 300});
    bar({.phase = ProgressPhase::transitions, .chain = 1, .states = 690, .transitions = 1080, .done = 690});
    bar({.phase = ProgressPhase::states, .chain = 2, .states = 310});
    const std::string at_work = bar.run_so_far("clock.def");
    CAPTURE(at_work);
    CHECK(at_work.starts_with("finding the states of chain 2 of clock.def (after "));
    CHECK(at_work.ends_with(" s: 1000 states and 1080 transitions found)"));
    bar({.phase = ProgressPhase::transitions, .chain = 2, .states = 310, .transitions = 20, .done = 310});
    bar.envisioned();
    const std::string answering = bar.run_so_far("clock.def");
    CAPTURE(answering);
    CHECK(answering.starts_with("answering from the envisionment of clock.def (after "));
    CHECK(answering.ends_with(" s: 1000 states and 1100 transitions found)"));
}
