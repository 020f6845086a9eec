// tests/cli/metric_scene_test.cpp: which scene files the scene command reads as metric scenes
// (is_metric_scene(), cli/scene_command.hpp).
#include "scene_command.hpp"
#include <doctest/doctest.h>

using qm::cli::is_metric_scene;

TEST_CASE("cli/scene_command: is_metric_scene reads past a byte-order mark, blanks and comments") {
    CHECK(is_metric_scene("(Defmechanism cam)"));
    CHECK(is_metric_scene("\xEF\xBB\xBF; a comment\n  ; another\n\n( DEFMECHANISM cam)"));
    CHECK_FALSE(is_metric_scene("(Defscene block)"));
    CHECK_FALSE(is_metric_scene("; (Defmechanism in a comment)\n(Defscene block)"));
    CHECK_FALSE(is_metric_scene(""));
    CHECK_FALSE(is_metric_scene("Defmechanism"));
    CHECK_FALSE(is_metric_scene("(Defmech"));
}
