// engine/builtins_qualitative.hpp
// Provides:   the qualitative vector maths of thesis section 2.3 as rule builtins. A direction value
//             is a tuple of signs `(+ 0 - ?)`; a single sign is a 1-tuple.
//   functions  sign-sum a b / sign-product a b (1-tuples; Tables 2.2 and 2.3), neg v, dot-sign a b
//              (the sign of the qualitative dot product, a 1-tuple), qsum a b (component-wise sign
//              sum), qsum-cancel a b (component-wise; opposite signs cancel to 0, the arithmetic of
//              Law 5's same-cause cancellation), rotate-90 v r (Def 14, 2-D: r = (+) turns (x y)
//              into (-y x), r = (-) into (y -x)), translations n / rotations n (Defs 1 and 4: every
//              direction of the dimension, the zero one included; rotations have 1 component in 2-D
//              and 3 in 3-D), zero-translation n, zero-rotation n, nearness v x (Def 38 rank 0..5).
//   tests      half-plane a b (dot sign + or 0), open-half-plane a b (dot sign +; an ambiguous dot
//              product counts as false: the liberal bias of section 7.3), zero? v, nonzero? v.
// Interim:    the sign arithmetic is written here because QUAL's engine/sign.hpp family was not in the
//             tree when this was written; these wrappers should call it once it is.
// Errors:     wrong value kinds, mismatched dimensions, 3-D rotate-90, dimensions other than 2 and 3.
// Knows nothing of the ATMS and of laws: this is mathematics, not mechanics.
#pragma once
#include "engine/builtin_registry.hpp"

namespace qm::engine {
void register_qualitative_builtins(BuiltinRegistry& r);
}
