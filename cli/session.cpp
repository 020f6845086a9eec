// cli/session.cpp: the interactive mode of `qm-atms SCENE.def -i` (cli/session.hpp).
#include "session.hpp"
#include "analysis/analysis.hpp"
#include "analysis/result_printer.hpp"
#include "query_text.hpp"
#include "scene/scene_parser.hpp"
#include "scene/what_if.hpp"
#include "scene_options.hpp"
#include <iostream>
#include <optional>
#include <unistd.h>

namespace qm::cli {
namespace {

// Queries against the loaded analysis, without reloading anything.
class Session {
public:
    Session(analysis::Analysis& analysis, bool json, std::ostream& out, std::ostream& err)
        : analysis_(analysis), json_(json), out_(out), err_(err) {}

    void run(std::istream& in) {
        const bool tty = isatty(STDIN_FILENO) && &in == &std::cin;
        std::string line;
        if (tty) out_ << "qm-atms: " << analysis_.scene().name << ", " << analysis_.situations().size()
                      << " situation(s). Type help.\n";
        for (;;) {
            if (tty) out_ << "qm-atms[" << situation_ << "]> " << std::flush;
            if (!std::getline(in, line)) break;
            if (!command(trim(line))) break;
            out_.flush();
        }
    }

private:
    static std::string trim(const std::string& s) {
        const auto b = s.find_first_not_of(" \t\r");
        if (b == std::string::npos) return {};
        return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
    }

    bool command(const std::string& line) {
        if (line.empty() || line[0] == '#') return true;
        const auto space = line.find(' ');
        const std::string verb = line.substr(0, space);
        const std::string rest = space == std::string::npos ? std::string() : trim(line.substr(space + 1));
        const scene::Scene& scene = analysis_.scene();
        const analysis::SituationResult& current = analysis_.situations()[situation_ - 1];
        Diagnostics d;
        if (verb == "quit" || verb == "exit") return false;
        if (verb == "help") out_ << help;
        else if (verb == "json") {
            json_ = rest.empty() ? !json_ : rest == "on";
            if (!rest.empty() && rest != "on" && rest != "off") err_ << "json: expected on or off\n";
            out_ << "json " << (json_ ? "on" : "off") << '\n';
        } else if (verb == "situation") {
            auto n = positive(rest);
            if (!n || *n > analysis_.situations().size())
                err_ << "situation: expected a number from 1 to " << analysis_.situations().size() << '\n';
            else situation_ = *n;
        } else if (verb == "freedom" || verb == "motions") {
            if (json_) {
                analysis::write_situation_json(out_, scene, current);
                out_ << '\n';
            } else if (verb == "freedom") analysis::print_freedom(out_, scene, current);
            else analysis::print_motions(out_, scene, current);
        } else if (verb == "why") {
            auto text = query_text(rest, "why", d);
            auto q = text ? scene::parse_query_fact(scene, *text, d, "why") : std::nullopt;
            if (q && scene::can_take_away(*q)) {
                d.error({"why", 1, 1}, "expected a motion or a freedom to explain (Translational-Motion, Rotational-Motion, "
                                       "Translational-Freedom, Rotational-Freedom), not a contact or force; "
                                       "`whatif` takes contacts and forces away");
                q.reset();
            }
            if (q)
                if (auto w = analysis_.why(*q, situation_, d))
                    json_ ? analysis::write_why_json(out_, *w) : analysis::print_why(out_, *w);
        } else if (verb == "given") {
            auto m = scene::parse_given(scene, rest, d, "given");
            if (m) show(analysis_.with_given(situation_, std::span<const scene::Motion>(&*m, 1), d));
        } else if (verb == "whatif") {
            const std::vector<scene::QueryFact> without = scene::read_whatif(scene, situation_, rest, d);
            if (!d.has_errors()) show(analysis_.what_if(situation_, without, d));
        } else {
            err_ << "unknown command '" << verb << "' (type help)\n";
        }
        d.print(err_);
        return true;
    }

    void show(const std::optional<analysis::SituationResult>& r) {
        if (!r) return;
        if (json_) {
            analysis::write_situation_json(out_, analysis_.scene(), *r);
            out_ << '\n';
        } else {
            analysis::print_situation(out_, analysis_.scene(), *r);
        }
    }

    static constexpr const char* help =
        "  situation N           ask about situation N from now on (1 is the first)\n"
        "  freedom               the free directions of every object\n"
        "  motions               every consistent combination of motions, and the stability verdict\n"
        "  why FACT              why a motion or freedom holds or was ruled out, e.g.\n"
        "                        why Rotational-Motion (follower (-))\n"
        "  given OBJ TRANS ROT   the situation with a current motion given, e.g. given pallet (0 0) (+)\n"
        "  whatif FACT[; FACT]   the situation with contacts or forces taken away, e.g.\n"
        "                        whatif Contact tb block-b-m; Force block\n"
        "  json [on|off]         answer in JSON (docs/OUTPUT.md)\n"
        "  help, quit\n";

    analysis::Analysis& analysis_;
    bool json_;
    std::size_t situation_ = 1;
    std::ostream& out_;
    std::ostream& err_;
};

}  // namespace

void run_session(analysis::Analysis& analysis, bool json, std::istream& in, std::ostream& out, std::ostream& err) {
    Session(analysis, json, out, err).run(in);
}

}  // namespace qm::cli
