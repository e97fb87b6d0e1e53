// The editor's script parsed without a window (examples/level_editor/editor_script_parse.hpp):
// every command read with its line, and a value that is not a finite number in range
// refused with the script's file and line before anything runs.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "editor_script_parse.hpp"

namespace tidewater::editor {
namespace {

TEST(EditorScript, CommandsAreReadWithTheirLines) {
    auto parsed = parse_script(
        "# a picture\ncamera 900 300 500 120 0 20 40\n\nbrush 640 330 120 -2.5\nriver brook discharge 13\n"
        "at 4 replace water.frag|a|b c\ntime 12.5\nat 9 brush 1 2 3 4\nat 10 river brook discharge 2\n",
        "s.script");
    ASSERT_TRUE(parsed.ok()) << parsed.error().message;
    ASSERT_EQ(parsed->size(), 7u);
    EXPECT_EQ((*parsed)[0].frame, -1) << "at the start";
    EXPECT_EQ((*parsed)[3].frame, 4);
    EXPECT_EQ((*parsed)[5].frame, 9);
    EXPECT_EQ(std::get<ScriptBrush>((*parsed)[5].command).radius, 3.0);
    EXPECT_EQ((*parsed)[6].frame, 10);
    EXPECT_EQ(std::get<ScriptRiver>((*parsed)[6].command).discharge, 2.0);
    EXPECT_EQ((*parsed)[0].number, 2);
    const auto& camera = std::get<ScriptCamera>((*parsed)[0].command);
    EXPECT_EQ(camera.position.x, 900.0);
    EXPECT_EQ(camera.fov_y_deg, 40.0);
    EXPECT_EQ(std::get<ScriptBrush>((*parsed)[1].command).height, -2.5);
    EXPECT_EQ((*parsed)[1].number, 4);
    EXPECT_EQ(std::get<ScriptRiver>((*parsed)[2].command).discharge, 13.0);
    EXPECT_EQ(std::get<ScriptStep>((*parsed)[3].command).argument, "water.frag|a|b c");
    EXPECT_EQ(std::get<ScriptTime>((*parsed)[4].command).seconds, 12.5);
}

TEST(EditorScript, ValuesOutOfRangeAreRefusedWithTheLine) {
    for (const char* line : {"camera nan 0 0 1 1 1",
                             "camera 0 0 0 1 1 1 0",
                             "camera 0 0 0 1 1 1 inf",
                             "probe 1e300 0",
                             "brush 0 0 -5 1",
                             "brush 0 0 5 nan",
                             "clip 0 0 0 0",
                             "river brook discharge -1",
                             "river brook width 3",
                             "viewports 3",
                             "viewports 1.5",
                             "at -1 screenshot a.png",
                             "at 3 print a.png",
                             "at 3 screenshot",
                             "screenshot a.png",
                             "replace a|b|c",
                             "at 3 at 4 time 1",
                             "at 2.5 time 1",
                             "at 4 brush 0 0 nan 1",
                             "time inf",
                             "camera 0 0 0 1 1 1 45 extra",
                             "fly to the moon"}) {
        auto parsed = parse_script(std::string("view shaded\n") + line + "\n", "bad.script");
        ASSERT_FALSE(parsed.ok()) << line;
        EXPECT_NE(parsed.error().message.find("bad.script:2: cannot read"), std::string::npos)
            << line << ": " << parsed.error().message;
    }
}

}  // namespace
}  // namespace tidewater::editor
