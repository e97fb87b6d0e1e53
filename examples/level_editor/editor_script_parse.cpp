#include "editor_script_parse.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <sstream>

namespace tidewater::editor {

namespace {

/// One line's words, read in order; fails on the first word that is missing or not in range.
class Words {
  public:
    explicit Words(const std::string& line) : in_(line) {}

    bool word(std::string& out) { return static_cast<bool>(in_ >> out); }
    bool number(double& out, double lo, double hi) {
        return static_cast<bool>(in_ >> out) && std::isfinite(out) && out >= lo && out <= hi;
    }
    bool coordinate(double& out) { return number(out, -kScriptMaxCoordinate, kScriptMaxCoordinate); }
    bool point(glm::dvec3& p) { return coordinate(p.x) && coordinate(p.y) && coordinate(p.z); }
    /// An optional last number: true when absent or in range.
    bool optional_number(double& out, double lo, double hi) {
        in_ >> std::ws;
        return in_.eof() || number(out, lo, hi);
    }
    /// The rest of the line, leading blanks dropped.
    std::string rest() {
        std::string r;
        std::getline(in_ >> std::ws, r);
        return r;
    }
    bool done() {
        in_ >> std::ws;
        return in_.eof();
    }

  private:
    std::istringstream in_;
};

std::optional<ScriptCommand> parse_line(const std::string& command, Words& w) {
    if (command == "camera" || command == "second") {
        ScriptCamera c;
        c.second = command == "second";
        if (!w.point(c.position) || !w.point(c.target) || !w.optional_number(c.fov_y_deg, 1.0, 170.0) || !w.done())
            return std::nullopt;
        return c;
    }
    if (command == "viewports") {
        double count = 0.0;
        if (!w.number(count, 1.0, 2.0) || count != std::floor(count) || !w.done()) return std::nullopt;
        return ScriptViewports{static_cast<int>(count)};
    }
    if (command == "view" || command == "preset") {
        std::string name;
        if (!w.word(name) || !w.done()) return std::nullopt;
        if (command == "view") return ScriptView{name};
        return ScriptPreset{name};
    }
    if (command == "probe") {
        ScriptProbe p;
        if (!w.coordinate(p.at.x) || !w.coordinate(p.at.y) || !w.done()) return std::nullopt;
        return p;
    }
    if (command == "brush") {
        ScriptBrush b;
        if (!w.coordinate(b.at.x) || !w.coordinate(b.at.y) || !w.number(b.radius, 1e-3, kScriptMaxCoordinate) ||
            !w.number(b.height, -1e4, 1e4) || !w.done())
            return std::nullopt;
        return b;
    }
    if (command == "river") {
        ScriptRiver r;
        std::string field;
        if (!w.word(r.name) || !w.word(field) || field != "discharge" || !w.number(r.discharge, 1e-6, 1e6) || !w.done())
            return std::nullopt;
        return r;
    }
    if (command == "clip") {
        ScriptClip c;
        if (!w.point(c.at) || !w.number(c.radius, 1e-3, kScriptMaxCoordinate) || !w.done()) return std::nullopt;
        return c;
    }
    if (command == "replace" || command == "screenshot") {  // only after "at N"
        ScriptStep s;
        s.kind = command;
        s.argument = w.rest();
        if (s.argument.empty()) return std::nullopt;
        return s;
    }
    if (command == "time") {
        ScriptTime t;
        if (!w.number(t.seconds, -86400.0, 86400.0) || !w.done()) return std::nullopt;
        return t;
    }
    return std::nullopt;
}

}  // namespace

Result<std::vector<ScriptLine>> parse_script(std::string_view text, const std::string& source) {
    std::vector<ScriptLine> commands;
    std::istringstream lines{std::string(text)};
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        Words words(line);
        std::string command;
        if (!words.word(command) || command[0] == '#') continue;
        // "at N COMMAND": the command runs before frame N is drawn; without it, at the start.
        long frame = -1;
        std::optional<ScriptCommand> parsed;
        if (command == "at") {
            double at = 0.0;
            if (words.number(at, 0.0, 1e9) && at == std::floor(at) && words.word(command) && command != "at") {
                frame = static_cast<long>(at);
                parsed = parse_line(command, words);
            }
        } else if (command != "replace" && command != "screenshot") {
            parsed = parse_line(command, words);
        }
        if (!parsed)
            return Error{ErrorCode::parse_error, fmt::format("{}:{}: cannot read \"{}\"", source, number, line)};
        commands.push_back({number, frame, std::move(*parsed)});
    }
    return commands;
}

}  // namespace tidewater::editor
