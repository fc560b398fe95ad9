// Replacement of a matched cell's interior (Damiand & Nivoliers 2022 §5.1, Algs. 3 and 4, read for
// G-maps). To replace an i-cell by an i-G-map pattern, only alpha_{i-1} is relinked at the
// boundary: alpha_0..alpha_{i-2} keep the boundary darts (alpha_j alpha_i is an involution for
// j <= i-2), so the pattern's boundary maps onto the cell's darts by the isomorphism f.
//  * every interior pattern dart x (not i-free) is copied as x^, with alpha_0..alpha_i copied
//    between copies, except that alpha_{i-1}(x) = d' on the boundary gives
//    alpha_{i-1}(x^) = f(d') (both ways);
//  * a face (i = 2) of a 3-G-map shared by two volumes is replaced on both half-faces: a mirror
//    copy x' with the same alpha_0..alpha_2 is linked to alpha_3(f(d')) and alpha_3(x^) = x'.
//    There is no orientation reversal in a G-map (the paper's Alg. 3 swaps beta_0 and beta_1 on
//    the second half-face; its printed loop is also wrong, see docs/query-replace.md);
//  * flags: a copied dart takes the flag of its pattern dart; the cell's darts keep theirs.
// Validity is kept (Theorem 2 for G-maps): the relinked alpha_{i-1} pairs are symmetric, and the
// cycle constraints hold because f commutes with alpha_0..alpha_{i-2} and the mirror copy commutes
// with alpha_3.
#pragma once
#include <vector>

#include "model/replace/flagged_map.hpp"
#include "model/replace/replacement_template.hpp"

namespace gmr::replace {

// f: the matched cell's boundary darts in label order (t.boundary of them). The copies are
// written into existing free darts: first .. first + k - 1, and for a shared face the mirror copies
// first + k .. first + 2k - 1 (k = t.interior); flags and positions must be sized to the map. The
// target's dimension must be i or i + 1 (query_replace checks it). Returns the darts written.
size_t replace_cell(FlaggedMap& target, const ReplacementTemplate& t, const Dart* f, Dart first,
                    bool shared);
// The same into new darts added at the end of the map (flags and positions grown with it).
size_t replace_cell(FlaggedMap& target, const ReplacementTemplate& t, const Dart* f, bool shared);

}  // namespace gmr::replace
