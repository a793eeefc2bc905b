#pragma once
// Dörfler's marking (W. Dörfler, "A convergent adaptive algorithm for Poisson's equation", SIAM
// J. Numer. Anal. 33 (1996) 1106-1124), the marking step of the adaptive loop
// solve -> estimate -> mark -> refine: the fewest triangles M whose indicators carry the
// fraction theta of the estimate's square,
//   sum over T in M of eta_T^2 >= theta * sum over all T of eta_T^2,
// taken greedily from the largest eta_T (ties by triangle number, so the marking is
// reproducible). theta in (0, 1]: small theta refines where the error is, theta = 1 everywhere.
#include <vector>

namespace sig {

/// The marked triangles (0-based, by decreasing eta_T). sig::Error for theta outside (0, 1] or
/// a negative indicator.
std::vector<int> dorfler_marking(const std::vector<double>& eta, double theta);

} // namespace sig
