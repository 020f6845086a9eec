// engine/program_cache.cpp: the compiled-rules cache on disk (program_cache.hpp).
#include "engine/program_cache.hpp"
#include "engine/rule_parser_source.hpp"
#include "qm/file_text.hpp"
#include <elf.h>
#include <link.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <fstream>
#include <functional>
#include <thread>
#include <unordered_map>

namespace qm::engine {
namespace {
namespace fs = std::filesystem;

// Bump when the encoding below changes. (A change of the engine's code needs no bump: the
// executable's identity is part of the key.)
constexpr std::uint32_t format_version = 1;
constexpr std::string_view magic = "QMRULES\n";
constexpr std::size_t header_bytes = 8 + 4 + 8 + 8;  // magic, version, payload length, checksum
// Entries of the bundled laws take about 120 kB; a decoded entry holds at most about 8 bytes of
// structure per byte read, so this bounds what a corrupt or crafted entry can make the reader allocate.
constexpr std::size_t max_entry_bytes = std::size_t{8} << 20;
constexpr std::size_t max_term_depth = 256;
constexpr std::string_view entry_suffix = ".qmrules";
constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";  // SourceText drops it

// A 64-bit hash of bytes, eight at a time: detects a damaged entry and names an entry by its key
// (a collision only costs a miss: the key itself is compared).
std::uint64_t hash_bytes(std::string_view s) {
    auto mix = [](std::uint64_t h) {
        h ^= h >> 33;
        h *= 0xff51afd7ed558ccdull;
        h ^= h >> 33;
        h *= 0xc4ceb9fe1a85ec53ull;
        return h ^ (h >> 33);
    };
    std::uint64_t h = 0x9e3779b97f4a7c15ull ^ (s.size() * 0x100000001b3ull);
    std::size_t i = 0;
    for (; i + 8 <= s.size(); i += 8) {
        std::uint64_t w;
        std::memcpy(&w, s.data() + i, 8);
        h = (h ^ w) * 0x9e3779b97f4a7c15ull;
        h ^= h >> 29;
    }
    std::uint64_t tail = 0;
    std::memcpy(&tail, s.data() + i, s.size() - i);
    return mix(h ^ tail);
}

class Out {
public:
    void u8(std::uint8_t v) { bytes.push_back(static_cast<char>(v)); }
    void u32(std::uint32_t v) { bytes.append(reinterpret_cast<const char*>(&v), 4); }
    void u64(std::uint64_t v) { bytes.append(reinterpret_cast<const char*>(&v), 8); }
    void str(std::string_view s) {
        u32(static_cast<std::uint32_t>(s.size()));
        bytes.append(s);
    }
    void count(std::size_t n) { u32(static_cast<std::uint32_t>(n)); }
    // A location's file as an index into the table written before the program.
    void where(const SourceLocation& w) {
        auto [it, added] = file_index.try_emplace(w.file, static_cast<std::uint32_t>(files.size()));
        if (added) files.push_back(w.file);
        u32(it->second);
        u32(w.line);
        u32(w.column);
    }
    void term(const CompiledTerm& t) {
        u8(static_cast<std::uint8_t>(t.kind));
        u32(t.constant.value);
        u32(t.slot);
        u32(t.function.value);
        count(t.args.size());
        for (const CompiledTerm& a : t.args) term(a);
    }
    void terms(const std::vector<CompiledTerm>& ts) {
        count(ts.size());
        for (const CompiledTerm& t : ts) term(t);
    }
    void atom(const CompiledAtom& a) {
        u32(a.predicate.value);
        terms(a.args);
        where(a.where);
    }
    void test(const CompiledTest& t) {
        u32(t.test.value);
        terms(t.args);
        where(t.where);
    }
    void tests(const std::vector<CompiledTest>& ts) {
        count(ts.size());
        for (const CompiledTest& t : ts) test(t);
    }
    void ground(const std::vector<CompiledGroundAtom>& atoms) {
        count(atoms.size());
        for (const CompiledGroundAtom& a : atoms) {
            u32(a.predicate.value);
            count(a.args.size());
            for (ValueId v : a.args) u32(v.value);
            where(a.where);
        }
    }
    std::string bytes;
    std::vector<std::string> files;

private:
    std::unordered_map<std::string, std::uint32_t> file_index;
};

class In {
public:
    explicit In(std::string_view bytes) : s_(bytes) {}
    bool ok = true;
    std::uint8_t u8() {
        if (!need(1)) return 0;
        return static_cast<std::uint8_t>(s_[at_++]);
    }
    std::uint32_t u32() {
        std::uint32_t v = 0;
        if (need(4)) std::memcpy(&v, s_.data() + at_, 4), at_ += 4;
        return v;
    }
    std::uint64_t u64() {
        std::uint64_t v = 0;
        if (need(8)) std::memcpy(&v, s_.data() + at_, 8), at_ += 8;
        return v;
    }
    std::string_view view() {
        const std::uint32_t n = u32();
        if (!need(n)) return {};
        std::string_view v = s_.substr(at_, n);
        at_ += n;
        return v;
    }
    std::string str() { return std::string(view()); }
    // A count of items each at least min_bytes long: never more than the bytes left could hold.
    std::size_t count(std::size_t min_bytes) {
        const std::uint32_t n = u32();
        if (n > (s_.size() - at_) / min_bytes) ok = false;
        return ok ? n : 0;
    }
    // v, checked to be below limit.
    std::uint32_t below(std::uint32_t v, std::size_t limit) {
        if (v >= limit) ok = false;
        return ok ? v : 0;
    }
    [[nodiscard]] bool at_end() const noexcept { return at_ == s_.size(); }

private:
    bool need(std::size_t n) {
        if (ok && n <= s_.size() - at_) return true;
        ok = false;
        return false;
    }
    std::string_view s_;
    std::size_t at_ = 0;
};

// Reads the program's body back, every id checked against what it indexes.
class ProgramReader {
public:
    ProgramReader(In& in, const std::vector<std::string>& files, std::size_t values, const BuiltinRegistry& builtins)
        : in_(in), files_(files), values_(values), builtins_(builtins.size()), registry_(builtins) {}

    CompiledProgram program() {
        CompiledProgram p;
        const std::size_t rules = in_.count(8);
        for (std::size_t i = 0; i < rules && in_.ok; ++i) p.rules.push_back(rule());
        ground(p.premises);
        ground(p.assumptions);
        const std::size_t prefs = in_.count(8);
        for (std::size_t i = 0; i < prefs && in_.ok; ++i) {
            CompiledPreference c;
            c.choice = value();
            c.rank = value();
            const std::size_t keys = in_.count(4);
            // Places among the rank predicate's arguments, of which there are keys + 1.
            for (std::size_t k = 0; k < keys && in_.ok; ++k) c.key.push_back(in_.below(in_.u32(), keys + 1));
            c.rank_at = in_.below(in_.u32(), keys + 1);
            if (in_.u8() != 0) c.up_to = static_cast<std::int64_t>(in_.u64());
            c.where = where();
            p.preferences.push_back(std::move(c));
        }
        p.stratum_count = in_.u32();
        for (const CompiledRule& r : p.rules)
            if (r.stratum >= p.stratum_count) in_.ok = false;
        return p;
    }

private:
    ValueId value() { return ValueId{in_.below(in_.u32(), values_)}; }
    BuiltinId builtin() { return BuiltinId{in_.below(in_.u32(), builtins_)}; }
    SourceLocation where() {
        SourceLocation w;
        const std::uint32_t f = in_.below(in_.u32(), files_.size());
        if (in_.ok) w.file = files_[f];
        w.line = in_.u32();
        w.column = in_.u32();
        return w;
    }
    CompiledTerm term(std::size_t depth) {
        CompiledTerm t;
        const std::uint8_t kind = in_.u8();
        if (kind > static_cast<std::uint8_t>(CompiledTerm::Kind::call) || depth > max_term_depth) in_.ok = false;
        t.kind = static_cast<CompiledTerm::Kind>(kind);
        const std::uint32_t constant = in_.u32(), slot = in_.u32(), function = in_.u32();
        // Only the field of the term's kind is an index; the others are written as defaulted.
        t.constant = ValueId{t.kind == CompiledTerm::Kind::constant ? in_.below(constant, values_) : constant};
        t.slot = t.kind == CompiledTerm::Kind::variable ? in_.below(slot, slots_) : slot;
        t.function = BuiltinId{t.kind == CompiledTerm::Kind::call ? in_.below(function, builtins_) : function};
        t.args = terms(depth + 1);
        if (t.kind == CompiledTerm::Kind::call && in_.ok) within_arity(t.function, t.args.size());
        return t;
    }
    std::vector<CompiledTerm> terms(std::size_t depth = 0) {
        std::vector<CompiledTerm> out;
        const std::size_t n = in_.count(17);
        out.reserve(n);
        for (std::size_t i = 0; i < n && in_.ok; ++i) out.push_back(term(depth));
        return out;
    }
    CompiledAtom atom() {
        CompiledAtom a;
        a.predicate = value();
        a.args = terms();
        a.where = where();
        return a;
    }
    CompiledTest test() {
        CompiledTest t;
        t.test = builtin();
        t.args = terms();
        t.where = where();
        return t;
    }
    // Builtins index their arguments: a call or test read back must have as many as the builtin takes.
    void within_arity(BuiltinId b, std::size_t args) {
        const Builtin& x = registry_.get(b);
        if (args < x.min_arity || args > x.max_arity) in_.ok = false;
    }
    std::vector<CompiledTest> tests() {
        std::vector<CompiledTest> out;
        const std::size_t n = in_.count(20);
        for (std::size_t i = 0; i < n && in_.ok; ++i) {
            out.push_back(test());
            if (in_.ok) within_arity(out.back().test, out.back().args.size());
        }
        return out;
    }
    Slot slot() { return in_.below(in_.u32(), slots_); }
    CompiledRule rule() {
        CompiledRule r;
        r.name = in_.str();
        r.where = where();
        const std::size_t slots = in_.count(4);
        for (std::size_t i = 0; i < slots && in_.ok; ++i) r.slot_names.push_back(in_.str());
        slots_ = r.slot_names.size();
        const std::size_t conditions = in_.count(16);
        for (std::size_t i = 0; i < conditions && in_.ok; ++i) {
            CompiledCondition c;
            const std::uint8_t kind = in_.u8();
            if (kind > static_cast<std::uint8_t>(CompiledCondition::Kind::aggregate)) in_.ok = false;
            c.kind = static_cast<CompiledCondition::Kind>(kind);
            c.atom = atom();
            c.test = test();
            if (c.kind == CompiledCondition::Kind::test && in_.ok) within_arity(c.test.test, c.test.args.size());
            c.slot = in_.u32();  // a quantified variable or an aggregate's result: a slot, or 0 unused
            if (c.slot >= std::max<std::size_t>(slots_, 1)) in_.ok = false;
            c.set = term(0);
            c.tests = tests();
            const std::size_t atoms = in_.count(16);
            for (std::size_t k = 0; k < atoms && in_.ok; ++k) c.atoms.push_back(atom());
            c.function = BuiltinId{in_.u32()};
            if (c.kind == CompiledCondition::Kind::aggregate) {
                c.function = BuiltinId{in_.below(c.function.value, builtins_)};
                if (in_.ok) within_arity(c.function, 2);  // folded as function(total, value)
            }
            c.value = term(0);
            c.start = term(0);
            const std::size_t locals = in_.count(4);
            for (std::size_t k = 0; k < locals && in_.ok; ++k) c.local_slots.push_back(slot());
            c.where = where();
            r.conditions.push_back(std::move(c));
        }
        const std::size_t consequents = in_.count(16);
        for (std::size_t i = 0; i < consequents && in_.ok; ++i) {
            CompiledConsequent c;
            const std::uint8_t kind = in_.u8();
            if (kind > static_cast<std::uint8_t>(CompiledConsequent::Kind::exactly_one)) in_.ok = false;
            c.kind = static_cast<CompiledConsequent::Kind>(kind);
            c.atom = atom();
            c.slot = in_.u32();
            if (c.slot >= std::max<std::size_t>(slots_, 1)) in_.ok = false;
            c.set = term(0);
            c.tests = tests();
            c.where = where();
            r.consequents.push_back(std::move(c));
        }
        r.stratum = in_.u32();
        r.non_monotonic = in_.u8() != 0;
        slots_ = 0;
        return r;
    }
    void ground(std::vector<CompiledGroundAtom>& into) {
        const std::size_t n = in_.count(20);
        for (std::size_t i = 0; i < n && in_.ok; ++i) {
            CompiledGroundAtom g;
            g.predicate = value();
            const std::size_t args = in_.count(4);
            for (std::size_t k = 0; k < args && in_.ok; ++k) g.args.push_back(value());
            g.where = where();
            into.push_back(std::move(g));
        }
    }

    In& in_;
    const std::vector<std::string>& files_;
    std::size_t values_, builtins_;
    const BuiltinRegistry& registry_;
    std::size_t slots_ = 0;  // the current rule's
};

void write_body(Out& o, const LoadedProgram& loaded) {
    const CompiledProgram& p = loaded.program;
    o.count(p.rules.size());
    for (const CompiledRule& r : p.rules) {
        o.str(r.name);
        o.where(r.where);
        o.count(r.slot_names.size());
        for (const std::string& s : r.slot_names) o.str(s);
        o.count(r.conditions.size());
        for (const CompiledCondition& c : r.conditions) {
            o.u8(static_cast<std::uint8_t>(c.kind));
            o.atom(c.atom);
            o.test(c.test);
            o.u32(c.slot);
            o.term(c.set);
            o.tests(c.tests);
            o.count(c.atoms.size());
            for (const CompiledAtom& a : c.atoms) o.atom(a);
            o.u32(c.function.value);
            o.term(c.value);
            o.term(c.start);
            o.count(c.local_slots.size());
            for (Slot s : c.local_slots) o.u32(s);
            o.where(c.where);
        }
        o.count(r.consequents.size());
        for (const CompiledConsequent& c : r.consequents) {
            o.u8(static_cast<std::uint8_t>(c.kind));
            o.atom(c.atom);
            o.u32(c.slot);
            o.term(c.set);
            o.tests(c.tests);
            o.where(c.where);
        }
        o.u32(r.stratum);
        o.u8(r.non_monotonic ? 1 : 0);
    }
    o.ground(p.premises);
    o.ground(p.assumptions);
    o.count(p.preferences.size());
    for (const CompiledPreference& c : p.preferences) {
        o.u32(c.choice.value);
        o.u32(c.rank.value);
        o.count(c.key.size());
        for (std::uint32_t k : c.key) o.u32(k);
        o.u32(c.rank_at);
        o.u8(c.up_to ? 1 : 0);
        if (c.up_to) o.u64(static_cast<std::uint64_t>(*c.up_to));
        o.where(c.where);
    }
    o.u32(p.stratum_count);
}

void write_values(Out& o, const ValueTable& values) {
    o.count(values.size());
    for (std::uint32_t i = 0; i < values.size(); ++i) {
        const Value& v = values.value(ValueId{i});
        o.u8(static_cast<std::uint8_t>(v.kind));
        switch (v.kind) {
            case ValueKind::integer: o.u64(static_cast<std::uint64_t>(v.integer)); break;
            case ValueKind::symbol:
            case ValueKind::direction: o.str(v.text); break;
            case ValueKind::set:
                o.count(v.elements.size());
                for (ValueId e : v.elements) o.u32(e.value);
                break;
        }
    }
}

// Interns the values again in their order: each must come back with its own id.
bool read_values(In& in, ValueTable& values) {
    const std::size_t n = in.count(1);
    for (std::uint32_t i = 0; i < n && in.ok; ++i) {
        const std::uint8_t kind = in.u8();
        std::optional<ValueId> id;
        switch (kind) {
            case static_cast<std::uint8_t>(ValueKind::integer): id = values.integer(static_cast<std::int64_t>(in.u64())); break;
            case static_cast<std::uint8_t>(ValueKind::symbol): {
                const std::string_view s = in.view();
                if (in.ok && !s.empty()) id = values.symbol(s);
                break;
            }
            case static_cast<std::uint8_t>(ValueKind::direction): {
                const std::string_view s = in.view();
                if (in.ok && !s.empty() && s.find_first_not_of("+0-?") == std::string_view::npos) id = values.direction(s);
                break;
            }
            case static_cast<std::uint8_t>(ValueKind::set): {
                std::vector<ValueId> elements(in.count(4));
                for (ValueId& e : elements) e = ValueId{in.below(in.u32(), i)};
                if (in.ok) id = values.set(std::move(elements));
                break;
            }
            default: break;
        }
        if (!id || id->value != i) in.ok = false;
    }
    return in.ok;
}

std::string builtin_signature(const BuiltinRegistry& builtins) {
    Out o;
    o.count(builtins.size());
    for (std::uint32_t i = 0; i < builtins.size(); ++i) {
        const Builtin& b = builtins.get(BuiltinId{i});
        o.str(b.name);
        o.u8(static_cast<std::uint8_t>(b.kind));
        o.u32(b.min_arity);
        o.u32(b.max_arity);
    }
    return std::move(o.bytes);
}

// The GNU build id (a hash the linker takes of the whole linked file) of the object this code is
// linked into: a rebuild that changes any code changes it. Read from the loaded image, so it names
// the code running even under valgrind or after the file on disk was replaced.
struct BuildIdSearch {
    std::uintptr_t inside = 0;
    std::string id;
};
int find_build_id(dl_phdr_info* info, std::size_t, void* data) {
    auto* search = static_cast<BuildIdSearch*>(data);
    bool contains = false;
    for (std::size_t i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info->dlpi_phdr[i];
        const std::uintptr_t start = info->dlpi_addr + ph.p_vaddr;
        if (ph.p_type == PT_LOAD && search->inside >= start && search->inside < start + ph.p_memsz) contains = true;
    }
    if (!contains) return 0;
    for (std::size_t i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info->dlpi_phdr[i];
        if (ph.p_type != PT_NOTE) continue;
        const char* at = reinterpret_cast<const char*>(info->dlpi_addr + ph.p_vaddr);
        const char* end = at + ph.p_memsz;
        auto align4 = [](std::size_t n) { return (n + 3) & ~std::size_t{3}; };
        while (at + sizeof(ElfW(Nhdr)) <= end) {
            ElfW(Nhdr) note;
            std::memcpy(&note, at, sizeof note);
            const char* name = at + sizeof note;
            const char* desc = name + align4(note.n_namesz);
            if (desc + note.n_descsz > end) break;
            if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0 && note.n_descsz > 0) {
                search->id.assign(desc, note.n_descsz);
                return 1;
            }
            at = desc + align4(note.n_descsz);
        }
    }
    return 1;
}

std::optional<std::string> build_id() {
    BuildIdSearch search;
    search.inside = reinterpret_cast<std::uintptr_t>(&find_build_id);
    dl_iterate_phdr(&find_build_id, &search);
    if (search.id.empty()) return std::nullopt;
    return search.id;
}

// What the load depends on besides the files' texts; nullopt when the code cannot be identified.
std::optional<std::string> cache_key(std::span<const std::string> paths, const LawCheckOptions& laws) {
    const std::optional<std::string> code = build_id();
    if (!code) return std::nullopt;
    Out o;
    o.u32(format_version);
    o.str(*code);
    o.str(builtin_signature(default_builtins()));
    o.u8(laws.require_citations ? 1 : 0);
    o.count(laws.direction_arities.size());
    for (std::size_t a : laws.direction_arities) o.u64(a);
    o.count(paths.size());
    for (const std::string& p : paths) o.str(p);
    return std::move(o.bytes);
}

bool sources_unchanged(const std::vector<CachedSource>& sources) {
    for (const CachedSource& s : sources) {
        // A rule file is a regular file: an entry naming a device or a pipe is not read (it could
        // block or never end), only missed.
        std::error_code ec;
        if (!fs::is_regular_file(s.file, ec)) return false;
        const FileText now = read_file_text(s.file);
        if (!now.text) return false;
        std::string_view t = *now.text;
        if (t.starts_with(byte_order_mark)) t.remove_prefix(byte_order_mark.size());
        if (t != s.text) return false;
    }
    return true;
}

std::optional<std::string> read_entry(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < static_cast<std::streamoff>(header_bytes) || static_cast<std::size_t>(size) > max_entry_bytes) return std::nullopt;
    in.seekg(0);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    if (!in.read(bytes.data(), size)) return std::nullopt;
    return bytes;
}

// Keeps the newest max entries; also removes temporary files a writer left more than an hour ago.
void prune(const fs::path& dir) {
    std::error_code ec;
    std::vector<std::pair<fs::file_time_type, fs::path>> entries;
    const auto stale = fs::file_time_type::clock::now() - std::chrono::hours(1);
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const auto when = it->last_write_time(ec);
        if (ec) return;
        if (name.ends_with(entry_suffix)) entries.emplace_back(when, it->path());
        else if (name.find(std::string(entry_suffix) + ".tmp.") != std::string::npos && when < stale) fs::remove(it->path(), ec);
    }
    if (entries.size() <= program_cache_max_entries) return;
    std::sort(entries.begin(), entries.end());
    for (std::size_t i = 0; i + program_cache_max_entries < entries.size(); ++i) fs::remove(entries[i].second, ec);
}

void store(const fs::path& dir, const fs::path& entry, const std::string& bytes) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return;
    // Unique to this process and thread: no two writers ever share a temporary file.
    const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
    fs::path tmp = entry;
    tmp += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id())) +
           "." + std::to_string(now);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) return;
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) {
            fs::remove(tmp, ec);
            return;
        }
    }
    fs::rename(tmp, entry, ec);
    if (ec) {
        fs::remove(tmp, ec);
        return;
    }
    prune(dir);
}

std::string entry_name(const std::string& key) {
    static constexpr char hex[] = "0123456789abcdef";
    std::uint64_t h = hash_bytes(key);
    std::string name(16, '0');
    for (int i = 15; i >= 0; --i, h >>= 4) name[static_cast<std::size_t>(i)] = hex[h & 15];
    return name + std::string(entry_suffix);
}

}  // namespace

std::string encode_program(const std::string& key, const std::vector<CachedSource>& sources, const LoadedProgram& program,
                           const BuiltinRegistry& builtins) {
    Out body;
    write_body(body, program);
    Out payload;
    payload.str(key);
    payload.str(builtin_signature(builtins));
    payload.count(sources.size());
    for (const CachedSource& s : sources) {
        payload.str(s.file);
        payload.str(s.text);
    }
    write_values(payload, program.values);
    payload.count(program.citations.size());
    for (const auto& [file, cite] : program.citations) {
        payload.str(file);
        payload.str(cite);
    }
    payload.count(body.files.size());
    for (const std::string& f : body.files) payload.str(f);
    payload.bytes += body.bytes;
    Out out;
    out.bytes.append(magic);
    out.u32(format_version);
    out.u64(payload.bytes.size());
    out.u64(hash_bytes(payload.bytes));
    out.bytes += payload.bytes;
    return std::move(out.bytes);
}

std::optional<DecodedProgram> decode_program(std::string_view bytes, const std::string& key, const BuiltinRegistry& builtins) {
    if (bytes.size() < header_bytes || bytes.substr(0, magic.size()) != magic) return std::nullopt;
    In header(bytes.substr(magic.size(), header_bytes - magic.size()));
    if (header.u32() != format_version) return std::nullopt;
    const std::uint64_t length = header.u64();
    const std::uint64_t checksum = header.u64();
    const std::string_view payload = bytes.substr(header_bytes);
    if (!header.ok || length != payload.size() || hash_bytes(payload) != checksum) return std::nullopt;
    In in(payload);
    if (in.view() != key || !in.ok) return std::nullopt;
    if (in.view() != builtin_signature(builtins) || !in.ok) return std::nullopt;
    DecodedProgram out;
    const std::size_t sources = in.count(8);
    for (std::size_t i = 0; i < sources && in.ok; ++i) {
        CachedSource s;
        s.file = in.str();
        s.text = in.str();
        out.sources.push_back(std::move(s));
    }
    if (!read_values(in, out.program.values)) return std::nullopt;
    const std::size_t cites = in.count(8);
    for (std::size_t i = 0; i < cites && in.ok; ++i) {
        std::string file = in.str();
        out.program.citations.emplace(std::move(file), in.str());
    }
    std::vector<std::string> files(in.count(4));
    for (std::string& f : files) f = in.str();
    if (!in.ok) return std::nullopt;
    ProgramReader reader(in, files, out.program.values.size(), builtins);
    out.program.program = reader.program();
    if (!in.ok || !in.at_end()) return std::nullopt;
    return out;
}

std::optional<LoadedProgram> load_programs_cached(std::span<const std::string> paths, Diagnostics& diagnostics,
                                                  const LawCheckOptions& laws, const std::filesystem::path& cache_dir) {
    const std::optional<std::string> key = cache_dir.empty() ? std::nullopt : cache_key(paths, laws);
    if (!key) return load_programs(paths, diagnostics, laws);
    const fs::path entry = cache_dir / entry_name(*key);
    if (const std::optional<std::string> bytes = read_entry(entry))
        if (std::optional<DecodedProgram> hit = decode_program(*bytes, *key))
            if (sources_unchanged(hit->sources)) return std::move(hit->program);
    Diagnostics found;
    SourceTexts read;
    std::optional<LoadedProgram> program = load_programs(paths, found, laws, read);
    for (const Diagnostic& d : found.items()) diagnostics.add(d);
    if (program && found.items().empty()) {
        std::vector<CachedSource> sources;
        for (const auto& [file, text] : read.texts()) sources.push_back({file, text.text()});
        store(cache_dir, entry, encode_program(*key, sources, *program));
    }
    return program;
}

}  // namespace qm::engine
