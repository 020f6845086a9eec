// analysis/why_printer.cpp: the text and JSON forms of a "why" answer (analysis/why_printer.hpp).
#include "analysis/why_printer.hpp"
#include "qm/json.hpp"
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace qm::analysis {
namespace {
using qm::json_string;

// A subtree's identity: two occurrences with the same key print the same lines, so the second can
// refer to the first. Keys are built bottom-up once per node; occurrences are counted in reading
// order without entering a subtree already met (its inside is not shown again either).
class SubtreeKeys {
public:
    explicit SubtreeKeys(const WhyAnswer& w) {
        for (const Exclusion& x : w.exclusions) visit(x.derivation);
        for (const Exclusion& x : w.exclusions) tally(x.derivation);
    }
    [[nodiscard]] const std::string& key(const Derivation& d) const { return keys_.at(&d); }
    // Whether the subtree occurs more than once (or is referred to by a "derived above" node):
    // such a subtree gets a number where it is first shown.
    [[nodiscard]] bool shared(const Derivation& d) const {
        auto it = count_.find(key(d));
        return it != count_.end() && it->second > 1;
    }
    // The key of the first derived subtree of this fact (for a node marked shown_above), or empty.
    [[nodiscard]] std::string first_of_fact(const std::string& fact) const {
        auto it = first_of_fact_.find(fact);
        return it == first_of_fact_.end() ? std::string{} : it->second;
    }

    // The first node shown in full for this fact (a derivation or a premise), or nullptr.
    [[nodiscard]] const Derivation* first_node(const std::string& fact) const {
        auto it = first_node_.find(fact);
        return it == first_node_.end() ? nullptr : it->second;
    }

private:
    const std::string& visit(const Derivation& d) {
        std::string k = d.fact + '\x1f' + d.law + '\x1f' + d.source;
        for (const std::string& b : d.bindings) k += '\x1f' + b;
        k += '\x1e';
        for (const Derivation& f : d.from) k += visit(f) + '\x1d';
        const std::string& out = keys_[&d] = std::move(k);
        return out;
    }
    void tally(const Derivation& d) {
        if (d.shown_above) {
            // Refers to its fact's first derivation, met earlier in reading order: one more
            // occurrence of that subtree.
            if (auto it = first_of_fact_.find(d.fact); it != first_of_fact_.end()) ++count_[it->second];
            return;
        }
        first_node_.try_emplace(d.fact, &d);
        if (d.from.empty()) return;
        const std::string& k = key(d);
        first_of_fact_.try_emplace(d.fact, k);
        if (++count_[k] > 1) return;
        for (const Derivation& f : d.from) tally(f);
    }
    std::map<const Derivation*, std::string> keys_;
    std::map<std::string, std::size_t> count_;
    std::map<std::string, std::string> first_of_fact_;
    std::map<std::string, const Derivation*> first_node_;
};

std::size_t steps_in(const Derivation& d) {
    std::size_t n = 0;
    for (const Derivation& f : d.from) n += 1 + steps_in(f);
    return n;
}

std::string law_text(const Derivation& d) {
    std::string out = d.law;
    if (!d.citation.empty()) out += " (" + d.citation + ")";
    return out;
}

class TreePrinter {
public:
    // numbered: the subtrees that may get a number (those a later line refers to); nullptr: every
    // shared one.
    TreePrinter(std::ostream& os, const SubtreeKeys& keys, const WhyPrintOptions& options,
                const std::set<std::string>* numbered)
        : os_(os), keys_(keys), options_(options), numbered_(numbered) {}

    void print(const Derivation& d, const std::string& indent, std::size_t depth) {
        if (d.shown_above)
            // A premise met again is one line either way: show it, not a reference.
            if (const Derivation* first = keys_.first_node(d.fact); first && first->from.empty()) {
                print(*first, indent, depth);
                return;
            }
        os_ << indent;
        if (d.shown_above) {
            const std::string k = keys_.first_of_fact(d.fact);
            auto it = numbers_.find(k);
            if (it != numbers_.end() && it->second == 0) it = numbers_.end();
            if (it != numbers_.end()) referenced_.insert(k);
            os_ << d.fact << (it != numbers_.end() ? "  (see [" + std::to_string(it->second) + "])\n"
                                                  : "  (derived in a part cut short)\n");
            return;
        }
        const std::string& k = keys_.key(d);
        if (!d.from.empty())
            if (auto it = numbers_.find(k); it != numbers_.end() && it->second != 0) {
                referenced_.insert(k);
                os_ << d.fact << "  (see [" << it->second << "])\n";
                return;
            }
        const bool cut = !options_.full && depth >= options_.depth && !d.from.empty();
        if (!cut && keys_.shared(d) && !d.from.empty()) {
            // Shown once; a number only where a later line refers to it.
            const bool number = !numbered_ || numbered_->contains(k);
            numbers_[k] = number ? ++last_ : 0;
            if (number) os_ << '[' << last_ << "] ";
        }
        os_ << d.fact;
        // A law's citation the first time it is named; its bindings only in the full answer (the
        // fact already names what they bind).
        if (!d.law.empty()) os_ << "  <= " << (cited_.insert(d.law).second ? law_text(d) : d.law);
        if (!d.source.empty()) os_ << (d.law.empty() ? "  from " : " at ") << d.source;
        if (options_.full && !d.bindings.empty()) {
            os_ << "  {";
            for (std::size_t i = 0; i < d.bindings.size(); ++i) os_ << (i ? ", " : "") << d.bindings[i];
            os_ << '}';
        }
        if (cut) {
            cut_ = true;
            const std::size_t n = steps_in(d);
            os_ << "  ... (" << n << (n == 1 ? " step" : " steps") << " below)\n";
            return;
        }
        os_ << '\n';
        for (const Derivation& f : d.from) print(f, indent + "    ", depth + 1);
    }

    [[nodiscard]] bool cut() const noexcept { return cut_; }
    // The subtrees a line referred to by number.
    [[nodiscard]] const std::set<std::string>& referenced() const noexcept { return referenced_; }

private:
    std::ostream& os_;
    const SubtreeKeys& keys_;
    const WhyPrintOptions& options_;
    std::map<std::string, std::size_t> numbers_;  // subtree key -> the number it was shown with
    std::size_t last_ = 0;
    std::set<std::string> cited_;                 // laws whose citation has been printed
    bool cut_ = false;                            // some subtree was cut short
    const std::set<std::string>* numbered_;
    std::set<std::string> referenced_;
};

void print_items(std::ostream& os, const std::vector<std::string>& items) {
    os << '{';
    for (std::size_t k = 0; k < items.size(); ++k) os << (k ? ", " : "") << items[k];
    os << '}';
}

// The first line: the verdict, and for a fact ruled out the law that concludes the first reason's
// contradiction with what it rests on.
void print_verdict(std::ostream& os, const WhyAnswer& w) {
    os << w.query << " in situation " << w.situation << ": ";
    if (w.status == WhyAnswer::Status::holds) {
        os << "holds\n";
        return;
    }
    os << "ruled out";
    if (w.exclusions.empty()) {
        os << '\n';
        return;
    }
    const Exclusion& first = w.exclusions.front();
    if (!first.derivation.law.empty()) os << " by " << law_text(first.derivation);
    if (first.responsible.empty()) {
        os << ", from the scene's description alone";
    } else {
        os << ", resting on ";
        print_items(os, first.responsible);
    }
    if (w.exclusions.size() > 1) os << " (" << w.exclusions.size() << " reasons in all)";
    os << '\n';
}

void write_strings(std::ostream& os, const std::vector<std::string>& xs) {
    os << '[';
    for (std::size_t i = 0; i < xs.size(); ++i) os << (i ? ", " : "") << json_string(xs[i]);
    os << ']';
}

class TreeWriter {
public:
    explicit TreeWriter(const SubtreeKeys& keys) : keys_(keys) {}
    void write(std::ostream& os, const Derivation& d) {
        os << "{\"fact\": " << json_string(d.fact) << ", \"law\": " << json_string(d.law)
           << ", \"citation\": " << json_string(d.citation) << ", \"source\": " << json_string(d.source)
           << ", \"bindings\": ";
        write_strings(os, d.bindings);
        os << ", \"absent\": ";
        write_strings(os, d.absent);
        os << ", \"shown_above\": " << (d.shown_above ? "true" : "false") << ", \"ref\": ";
        const std::string k = d.shown_above ? keys_.first_of_fact(d.fact) : keys_.key(d);
        if ((d.shown_above && !k.empty()) || (!d.from.empty() && keys_.shared(d))) {
            auto [it, added] = numbers_.try_emplace(k, numbers_.size() + 1);
            os << it->second;
        } else {
            os << "null";
        }
        os << ", \"from\": [";
        for (std::size_t i = 0; i < d.from.size(); ++i) {
            if (i) os << ", ";
            write(os, d.from[i]);
        }
        os << "]}";
    }

private:
    const SubtreeKeys& keys_;
    std::map<std::string, std::size_t> numbers_;
};

// The reasons, their derivations shown as options say; returns the printer (which lines referred to
// which subtree, whether something was cut).
TreePrinter print_reasons(std::ostream& os, const WhyAnswer& w, const SubtreeKeys& keys, const WhyPrintOptions& options,
                          const std::set<std::string>* numbered) {
    TreePrinter trees(os, keys, options, numbered);
    const std::size_t shown = options.full ? w.exclusions.size() : std::min(w.exclusions.size(), options.reasons);
    for (std::size_t i = 0; i < w.exclusions.size(); ++i) {
        const Exclusion& x = w.exclusions[i];
        os << "  " << (w.exclusions.size() > 1 ? "Reason " + std::to_string(i + 1) : std::string("Reason"));
        if (x.responsible.empty()) {
            os << ": the scene's description alone (no contact, force or given motion)";
        } else {
            os << ": resting on ";
            print_items(os, x.responsible);
        }
        if (i >= shown) {  // beyond the cap: one line, its law
            if (!x.derivation.law.empty()) os << ", by " << x.derivation.law;
            os << '\n';
            continue;
        }
        os << '\n';
        trees.print(x.derivation, "    ", 0);
    }
    if (shown < w.exclusions.size())
        os << "  (the derivations of reasons " << shown + 1
           << (w.exclusions.size() > shown + 1 ? "-" + std::to_string(w.exclusions.size()) : std::string())
           << " and every step cut short: --full)\n";
    else if (trees.cut())
        os << "  (every step cut short: --full)\n";
    return trees;
}

}  // namespace

void print_why(std::ostream& os, const WhyAnswer& w, const WhyPrintOptions& options) {
    print_verdict(os, w);
    for (const std::string& n : w.notes) os << "  " << n << "\n";
    const SubtreeKeys keys(w);
    // Twice: the first time to learn which subtrees a visible line refers to, so that only those
    // carry a number.
    std::ostringstream dry;
    const std::set<std::string> referenced = print_reasons(dry, w, keys, options, nullptr).referenced();
    (void)print_reasons(os, w, keys, options, &referenced);
    if (!w.responsible_sets.empty()) {
        os << (w.responsible_minimal ? "  Responsible (contacts, forces and given motions; the minimal sets, each suffices):\n"
                                     : "  Responsible (contacts, forces and given motions; a set that suffices, maybe not minimal):\n");
        for (const auto& set : w.responsible_sets) {
            if (set.empty()) {
                os << "    {} (the scene's description alone)\n";
                continue;
            }
            os << "    ";
            print_items(os, set);
            os << '\n';
        }
    }
}

void write_why_json(std::ostream& os, const WhyAnswer& w) {
    os << "{\"query\": " << json_string(w.query) << ", \"situation\": " << w.situation << ", \"status\": "
       << (w.status == WhyAnswer::Status::holds ? "\"holds\"" : "\"ruled-out\"") << ", \"notes\": ";
    write_strings(os, w.notes);
    const SubtreeKeys keys(w);
    TreeWriter trees(keys);
    os << ", \"exclusions\": [";
    for (std::size_t i = 0; i < w.exclusions.size(); ++i) {
        os << (i ? ", " : "") << "{\"responsible\": ";
        write_strings(os, w.exclusions[i].responsible);
        os << ", \"derivation\": ";
        trees.write(os, w.exclusions[i].derivation);
        os << '}';
    }
    os << "], \"responsible_sets\": [";
    for (std::size_t i = 0; i < w.responsible_sets.size(); ++i) {
        if (i) os << ", ";
        write_strings(os, w.responsible_sets[i]);
    }
    os << "], \"responsible_minimal\": " << (w.responsible_minimal ? "true" : "false") << "}\n";
}

}  // namespace qm::analysis
