// geometry/metric_source.hpp
// Provides:   MetricSource, the text of one input to the metric scene reader (a file or the
//             CONFIG argument): qm::SourceText (qm/source_text.hpp),
//             and MetricPositions, which maps an AST node's position tag to its byte offset.
// Ownership:  value types.
#pragma once
#include "qm/diagnostics.hpp"
#include "qm/source_text.hpp"
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace qm::geometry {

// The text of a metric scene (or a CONFIG argument) with line/column lookup.
using MetricSource = qm::SourceText;

}  // namespace qm::geometry
