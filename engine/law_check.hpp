// engine/law_check.hpp
// Provides:   LawCheckOptions and check_laws(), the checks that apply to a program loaded as the laws
//             of a driver (every file of rules/, or of `--rules DIR`), beyond those of any program:
//               - warning: a file with rules and no `cite` item, or a `cite` that names no numbered
//                 part of the thesis (section, table, definition, law, figure, chapter, appendix):
//                 the citation is what `--why` prints beside each law (STYLE.md: every law cites);
//               - warning: a direction literal of two or more signs whose number of signs is none of
//                 the given arities (a 3-D direction in a law run on a 2-D scene can match nothing);
//                 one-sign directions are signs (Tables 2.2-2.3) and always allowed.
//             citations() gives each file's citation text, for explanations.
// Errors:     only warnings into diagnostics; never throws for bad input.
// Knows nothing of the ATMS or of mechanics: the caller says which arities a scene has and why.
#pragma once
#include "engine/rule_spec.hpp"
#include "qm/diagnostics.hpp"
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace qm::engine {

struct LawCheckOptions {
    bool require_citations = false;            // every file with a rule must `cite`
    std::vector<std::size_t> direction_arities;  // empty: no arity check
    std::string arity_context;                 // why those arities, e.g. "scene 'block' is 2-D (...)"
};

void check_laws(const ProgramSpec& spec, const LawCheckOptions& options, Diagnostics& diagnostics);

// File (as in source locations) -> its `cite` texts joined with "; ", in reading order.
[[nodiscard]] std::map<std::string, std::string> citations(const ProgramSpec& spec);

}  // namespace qm::engine
