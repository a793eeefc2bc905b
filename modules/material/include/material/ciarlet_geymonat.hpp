#pragma once
// The compressible law of Ciarlet and Geymonat, the thesis's "Ogden" W (1.63), used for the
// hyperelastic ring of Scenes 7b and 8b:
//
//   W(C) = c1 (I1 - 3) + c2 (I2 - 3) + a (I3 - 1) - (c1 + 2 c2 + a) ln I3,
//
// with I1, I2, I3 the invariants of the 3x3 C; the coefficient of ln I3 makes C = I stress
// free. Its small-strain limit is Hooke's law with lambda = 4 (a + c2), mu = 2 (c1 + c2) (GetFEM's
// Ciarlet-Geymonat parameters [lambda; mu; a'] = [4 (a + c2); 2 (c1 + c2); c1] give the same W
// up to a constant).
#include "material/hyperelastic.hpp"

namespace sig {

class CiarletGeymonat final : public HyperelasticLaw {
public:
  /// c1 > 0, c2 >= 0, a >= 0 (sig::Error otherwise).
  CiarletGeymonat(double c1, double c2, double a, PlaneMode plane = PlaneMode::strain);

  std::string name() const override { return "ciarlet-geymonat"; }
  double c1() const { return c1_; }
  double c2() const { return c2_; }
  double a() const { return a_; }

  /// S = 2 [c1 I + c2 (I1 I - C) + (a I3 - d) C^-1] with d = c1 + 2 c2 + a (thesis 1.61).
  MaterialPoint3d at(const Eigen::Matrix3d& C, bool with_tangent = true) const override;
  double lambda() const override { return 4.0 * (a_ + c2_); }
  double mu() const override { return 2.0 * (c1_ + c2_); }

private:
  MaterialPoint2d at_plane_strain(const Eigen::Matrix2d& C, bool with_tangent) const override;

  double c1_, c2_, a_;
};

} // namespace sig
