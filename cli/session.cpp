// cli/session.cpp: the interactive mode of `qm-atms SCENE.def -i` (cli/session.hpp).
#include "session.hpp"
#include "analysis/analysis.hpp"
#include "analysis/result_printer.hpp"
#include "analysis/why_printer.hpp"
#include "line_editor.hpp"
#include "query_text.hpp"
#include "qm/assert.hpp"
#include "qm/spelling.hpp"
#include "scene/scene_parser.hpp"
#include "scene/what_if.hpp"
#include "scene_options.hpp"
#include <array>
#include <optional>
#include <string_view>

namespace qm::cli {
namespace {

// One command: its name, what it takes (empty: nothing) and what it does, for `help`, for the
// usage message of a command given the wrong arguments, and for "did you mean".
struct Command {
    std::string_view name, arguments, example, does;
};
constexpr std::array commands = {
    Command{"situation", "N", "situation 2", "ask about situation N from now on (1 is the first)"},
    Command{"freedom", "", "", "the free directions of every object"},
    Command{"motions", "", "", "the consistent combinations of motions the forces select, and the stability verdict"},
    Command{"kinematic", "", "",
            "every kinematically consistent combination (blocking, pushing and given motions alone, before the forces choose)"},
    Command{"why", "FACT", "why Rotational-Motion (follower (-))", "why a motion or freedom holds or was ruled out"},
    Command{"given", "OBJ TRANS ROT", "given pallet (0 0) (+)", "the situation with a current motion given"},
    Command{"whatif", "Contact A B | Force OBJ [CAUSE] [; ...]", "whatif Contact tb block-b-m; Force block",
            "the situation with contacts or forces taken away"},
    Command{"with", "Contact A B | Force OBJ DIR ORIGIN [CAUSE] [; ...]", "with Force block (+ 0) (0 0) push",
            "the situation with contacts or forces added"},
    Command{"json", "[on|off]", "json on", "answer in JSON (docs/OUTPUT.md)"},
    Command{"full", "[on|off]", "full on", "show `why` answers whole: every reason and every step"},
    Command{"help", "", "", "this list"},
    Command{"quit", "", "", "leave (so does exit, or the end of the input)"},
};

const Command* find_command(std::string_view verb) {
    for (const Command& c : commands)
        if (c.name == verb) return &c;
    return nullptr;
}

std::string usage(const Command& c) {
    std::string out = "usage: " + std::string(c.name) + (c.arguments.empty() ? "" : " " + std::string(c.arguments));
    if (!c.example.empty()) out += ", e.g. " + std::string(c.example);
    return out + ": " + std::string(c.does);
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// Queries against the loaded analysis, without reloading anything.
class Session {
public:
    Session(analysis::Analysis& analysis, bool json, std::size_t situation, std::ostream& out, std::ostream& err)
        : analysis_(analysis), json_(json), situation_(situation), out_(out), err_(err) {}

    void run(std::istream& in) {
        LineInput input(in, out_);
        if (input.terminal())
            out_ << "qm-atms: " << analysis_.scene().name << ", " << analysis_.situations().size()
                 << " situation(s). Type help.\n";
        while (auto line = input.next("qm-atms[" + std::to_string(situation_) + "]> ")) {
            if (!command(trim(*line))) break;
            out_.flush();
        }
    }

private:
    bool command(const std::string& line) {
        if (line.empty() || line[0] == '#') return true;
        const auto space = line.find_first_of(" \t");
        const std::string verb = line.substr(0, space);
        const std::string rest = space == std::string::npos ? std::string() : trim(line.substr(space + 1));
        if (verb == "exit") return false;
        const Command* c = find_command(verb);
        if (!c) {
            std::vector<std::string_view> names;
            for (const Command& k : commands) names.push_back(k.name);
            err_ << "unknown command '" << verb << "'" << did_you_mean(verb, names) << " (type help)\n";
            return true;
        }
        if (c->name == "quit") return false;
        // Every command states what it takes: one taking nothing refuses arguments, one needing
        // some says what they are instead of failing on an empty text.
        const bool optional = c->arguments.empty() || c->arguments.front() == '[';
        if ((c->arguments.empty() && !rest.empty()) || (!optional && rest.empty())) {
            err_ << usage(*c) << '\n';
            return true;
        }
        Diagnostics d;
        answer(*c, rest, d);
        d.print(err_);
        return true;
    }

    void answer(const Command& c, const std::string& rest, Diagnostics& d) {
        const scene::Scene& scene = analysis_.scene();
        const analysis::SituationResult& current = analysis_.situations()[situation_ - 1];
        if (c.name == "help") {
            for (const Command& k : commands) {
                const std::string head = "  " + std::string(k.name) + (k.arguments.empty() ? "" : " " + std::string(k.arguments));
                out_ << head << std::string(head.size() < 24 ? 24 - head.size() : 1, ' ') << k.does << '\n';
                if (!k.example.empty()) out_ << std::string(24, ' ') << "e.g. " << k.example << '\n';
            }
        } else if (c.name == "json" || c.name == "full") {
            if (!rest.empty() && rest != "on" && rest != "off") {
                err_ << usage(c) << '\n';
                return;
            }
            bool& flag = c.name == "json" ? json_ : full_;
            flag = rest.empty() ? !flag : rest == "on";
            out_ << c.name << (flag ? " on" : " off") << '\n';
        } else if (c.name == "situation") {
            auto n = positive(rest);
            if (!n || *n > analysis_.situations().size())
                err_ << "situation: expected a number from 1 to " << analysis_.situations().size() << ", but found '" << rest
                     << "'\n";
            else situation_ = *n;
        } else if (c.name == "freedom" || c.name == "motions" || c.name == "kinematic") {
            const auto set = c.name == "kinematic" ? analysis::MotionSet::kinematic : analysis::MotionSet::selected;
            if (json_) {
                analysis::write_situation_json(out_, scene, current, set);
                out_ << '\n';
            } else if (c.name == "freedom") analysis::print_freedom(out_, scene, current);
            else analysis::print_motions(out_, scene, current, set);
        } else if (c.name == "why") {
            why(rest, d);
        } else if (c.name == "given") {
            auto m = scene::parse_given(scene, rest, d, "given");
            if (m) show(analysis_.with_given(situation_, std::span<const scene::Motion>(&*m, 1), d));
        } else if (c.name == "whatif") {
            const std::vector<scene::QueryFact> without = scene::read_whatif(scene, situation_, rest, d);
            if (!d.has_errors()) show(analysis_.what_if(situation_, without, d));
        } else if (c.name == "with") {
            const scene::Additions added = scene::read_with(scene, situation_, rest, d);
            if (!d.has_errors()) show(analysis_.what_if_with(situation_, added, d));
        }
    }

    void why(const std::string& rest, Diagnostics& d) {
        auto text = query_text(rest, "why", d);
        auto q = text ? scene::parse_query_fact(analysis_.scene(), *text, d, "why") : std::nullopt;
        if (q && scene::can_take_away(*q)) {
            d.error({"why", 1, 1}, "expected a motion or a freedom to explain (Translational-Motion, Rotational-Motion, "
                                   "Translational-Freedom, Rotational-Freedom), not a contact or force; "
                                   "`whatif` takes contacts and forces away, `with` adds them");
            q.reset();
        }
        if (q)
            if (auto w = analysis_.why(*q, situation_, d)) json_ ? analysis::write_why_json(out_, *w) : analysis::print_why(out_, *w, {.full = full_});
    }

    void show(const std::optional<analysis::SituationResult>& r) {
        if (!r) return;
        if (json_) {  // JSON has no place for notes: standard error, as beside `--json`
            analysis::write_situation_json(out_, analysis_.scene(), *r);
            out_ << '\n';
            for (const std::string& n : r->notes) err_ << "qm-atms: note: situation " << r->index << ": " << n << '\n';
        } else {
            analysis::print_situation(out_, analysis_.scene(), *r);
        }
    }

    analysis::Analysis& analysis_;
    bool json_;
    bool full_ = false;  // `full on`: why answers whole
    std::size_t situation_;
    std::ostream& out_;
    std::ostream& err_;
};

}  // namespace

void run_session(analysis::Analysis& analysis, bool json, std::size_t situation, std::istream& in, std::ostream& out, std::ostream& err) {
    QM_REQUIRE(situation >= 1 && situation <= analysis.situations().size(), "a situation of the analysis");
    Session(analysis, json, situation, out, err).run(in);
}

}  // namespace qm::cli
