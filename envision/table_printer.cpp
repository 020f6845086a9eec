// envision/table_printer.cpp: the layout of Appendices A-D.
#include "envision/table_printer.hpp"

#include <algorithm>
#include <map>

namespace qm::envision {

namespace {

class ChainTable {
public:
    ChainTable(const geometry::Mechanism& m, const Envisionment& e, const ChainEnvisionment& c) : m_(m), e_(e), c_(c) {
        column_pair_ = 0;
        for (std::size_t k = 0; k < c.chain.pairs.size(); ++k) {
            const std::size_t n = e.pairs[c.chain.pairs[k]].vocabulary.places.size();
            if (n > e.pairs[c.chain.pairs[column_pair_]].vocabulary.places.size()) column_pair_ = k;
            if (n > 1) shown_pairs_.push_back(k);
        }
        if (shown_pairs_.empty()) shown_pairs_.push_back(0);
        const auto& spec = e.pairs[c.chain.pairs[column_pair_]].spec;
        a_ = c.chain.object_index(spec.a);
        b_ = c.chain.object_index(spec.b);
    }

    void write(std::ostream& os) {
        const auto& pair = e_.pairs[c_.chain.pairs[column_pair_]];
        os << "chain " << c_.chain.index + 1 << ": rows: place of " << shown_names() << "; columns: motions of "
           << m_.parts[pair.spec.a].name << " / " << m_.parts[pair.spec.b].name << '\n';
        // Cells by row (place vector) and column.
        std::map<std::vector<std::uint32_t>, std::array<std::vector<std::string>, 9>> rows;
        std::vector<std::vector<const Transition*>> out(c_.states.size());
        for (const auto& t : c_.transitions) out[t.from.value].push_back(&t);
        for (std::uint32_t i = 0; i < c_.states.size(); ++i) {
            if (!c_.is_shown(StateId{i})) continue;
            const State& s = c_.states[StateId{i}];
            auto& cell = rows[place_key(s)][column(s)];
            if (several_per_cell()) cell.push_back("[" + others(s) + "]");
            for (const Transition* t : out[i]) cell.push_back(entry(c_.states[t->to]) + (t->duration == Duration::instant ? " i" : ""));
            if (out[i].empty()) cell.push_back(".");
        }
        std::vector<std::string> header{"place"};
        for (int x = -1; x <= 1; ++x)
            for (int y = -1; y <= 1; ++y) header.push_back(std::string(sign_word(static_cast<std::int8_t>(x))) + sign_word(static_cast<std::int8_t>(y)));
        std::vector<std::size_t> width(header.size(), 0);
        for (std::size_t i = 0; i < header.size(); ++i) width[i] = header[i].size();
        for (const auto& [key, cells] : rows) {
            width[0] = std::max(width[0], row_label(key).size());
            for (std::size_t j = 0; j < 9; ++j)
                for (const auto& line : cells[j]) width[j + 1] = std::max(width[j + 1], line.size());
        }
        auto line_of = [&](const std::vector<std::string>& cells) {
            std::string out;
            for (std::size_t i = 0; i < cells.size(); ++i) {
                out += (i ? " | " : "") + cells[i] + std::string(width[i] - cells[i].size(), ' ');
            }
            while (!out.empty() && out.back() == ' ') out.pop_back();
            return out + '\n';
        };
        os << line_of(header);
        std::string rule;
        for (std::size_t i = 0; i < width.size(); ++i) rule += (i ? "-+-" : "") + std::string(width[i], '-');
        os << rule << '\n';
        for (const auto& [key, cells] : rows) {
            std::size_t height = 1;
            for (const auto& cell : cells) height = std::max(height, cell.size());
            for (std::size_t r = 0; r < height; ++r) {
                std::vector<std::string> line{r == 0 ? row_label(key) : ""};
                for (const auto& cell : cells) line.push_back(r < cell.size() ? cell[r] : "");
                os << line_of(line);
            }
        }
    }

private:
    std::string shown_names() const {
        std::string out;
        for (std::size_t i = 0; i < shown_pairs_.size(); ++i) out += (i ? " / " : "") + e_.pairs[c_.chain.pairs[shown_pairs_[i]]].name;
        return out;
    }
    std::vector<std::uint32_t> place_key(const State& s) const {
        std::vector<std::uint32_t> k;
        for (const std::size_t p : shown_pairs_) k.push_back(s.places[p].value);
        return k;
    }
    std::string row_label(const std::vector<std::uint32_t>& key) const {
        std::string out;
        for (std::size_t i = 0; i < key.size(); ++i) out += (i ? "/" : "") + std::to_string(key[i]);
        return out;
    }
    std::size_t column(const State& s) const { return static_cast<std::size_t>((s.motions[a_] + 1) * 3 + (s.motions[b_] + 1)); }
    std::string entry(const State& s) const {
        return row_label(place_key(s)) + " " + sign_word(s.motions[a_]) + " " + sign_word(s.motions[b_]);
    }
    std::string others(const State& s) const {
        std::string out;
        for (std::size_t o = 0; o < s.motions.size(); ++o)
            if (o != a_ && o != b_) out += (out.empty() ? "" : " ") + m_.parts[c_.chain.objects[o]].name + " " + sign_word(s.motions[o]);
        return out;
    }
    // Do some row and column hold more than one state (other objects' motions not fixed)?
    bool several_per_cell() {
        if (!several_) {
            std::map<std::pair<std::vector<std::uint32_t>, std::size_t>, int> seen;
            bool many = false;
            for (const State& s : c_.states.states()) many = many || ++seen[{place_key(s), column(s)}] > 1;
            several_ = many;
        }
        return *several_;
    }

    const geometry::Mechanism& m_;
    const Envisionment& e_;
    const ChainEnvisionment& c_;
    std::size_t column_pair_ = 0, a_ = 0, b_ = 0;
    std::vector<std::size_t> shown_pairs_;
    std::optional<bool> several_;
};

}  // namespace

void write_table(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e) {
    os << "mechanism " << e.mechanism << '\n';
    for (const auto& c : e.chains) ChainTable(m, e, c).write(os);
}

}  // namespace qm::envision
