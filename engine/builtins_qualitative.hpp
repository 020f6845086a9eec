// engine/builtins_qualitative.hpp
// Provides:   the qualitative vector maths of thesis section 2.3 as rule builtins. A direction value
//             is a tuple of signs `(+ 0 - ?)`; a single sign is a 1-tuple.
//   functions  sign-sum a b / sign-product a b (1-tuples; Tables 2.2 and 2.3), neg v, dot-sign a b
//              (the sign of the qualitative dot product, a 1-tuple), qsum a b (component-wise sign
//              sum, associative, so it folds in aggregates), cancel-ambiguous v (every `?` becomes 0:
//              applied to a qsum of forces with one cause it is Law 5's same-cause cancellation, since
//              such a sum is ambiguous exactly where + and - met), rotate-90 v r (Def 14; 2-D: r = (+)
//              turns (x y) into (-y x), r = (-) into (y -x); 3-D: per axis of r (Table 2.1), the
//              quarter turns e x v summed; a zero rotation gives the zero vector), translations n /
//              rotations n (Defs 1 and 4: every direction of the dimension, the zero one included;
//              translations for n = 1..8, 3^n of them; rotations only for n = 2 (1 component) and
//              n = 3 (3 components), the only ones the thesis defines, Table 2.1), zero-translation n
//              (n = 1..8), zero-rotation n (n = 2, 3), resolve-as v x (v with each `?` replaced by x's
//              sign there: the resolution of v, section 2.3, that agrees with x where v is ambiguous),
//              qsum-of s (the qualitative sum of a set's directions; a direction is its own sum),
//              set-add s x (s with x added; to collect values in an aggregate), qsum-compared a b w
//              (qsum when the magnitudes are known to compare as w, the sign of |a| - |b|: where a and b
//              have opposite signs the larger one's sign, 0 for (0), ? for (?); elsewhere as qsum),
//              components v (the number of signs of v), component v i (the i-th sign, 1-based, as a
//              1-tuple), with-component v i s (v with its i-th sign replaced by the 1-tuple s).
//   tests      half-plane a b (dot sign + or 0), open-half-plane a b (dot sign +; an ambiguous dot
//              product counts as false: the liberal bias of section 7.3), outside-open-half-plane a b
//              (the negation of open-half-plane), zero? v, nonzero? v.
//   sets       neg and rotate-90 map over a set of directions; the three half-plane tests take a
//              direction or a set of directions in either place and hold iff they hold for every
//              pair (outside-: for no pair), i.e. a set stands for the intersection of its elements'
//              half planes (the potential contacts of two corners, Def 26).
// Errors:     wrong value kinds, mismatched dimensions, a rotation of the wrong arity, a translation
//             dimension outside 1..8, a rotation dimension other than 2 and 3, a component number
//             outside 1..the direction's size.
// Knows nothing of the ATMS and of laws: this is mathematics, not mechanics.
#pragma once
#include "engine/builtin_registry.hpp"

namespace qm::engine {
void register_qualitative_builtins(BuiltinRegistry& r);
}
