#include "core/datafile.hpp"

namespace sig {

// Every card a stage reads. Choices are checked where they are read (Card::choice), so the help
// text lists them for the card reference (datafiles/CARDS.md, sig-dump --cards-markdown).
const std::vector<CardSpec>& card_schema() {
  static const std::vector<CardSpec> schema = {
      {"TITLE",
       false,
       "free text: the rest of the line is the case title (80 characters kept in DS headers)",
       {}},
      {"MESH",
       false,
       "the mesh: a generated thesis geometry or a mesh file",
       {
           {"generator",
            "half-disc | disc | ring | rectangle | square (2D) | box | half-ball | ball | cylinder "
            "(3D)"},
           {"file", "mesh file: gmsh .msh (2.2 or 4.1, ASCII or binary), FreeFem .msh or MODULEF "
                    ".nopo; relative to the datafile's folder"},
           {"coincident",
            "error | allow: nodes of a mesh file at the same place that the "
            "triangles do not share (an open crack) are an error unless allowed",
            "error"},
           {"R", "radius of the disc, half disc, ball, half ball or cylinder"},
           {"L", "length of the cylinder (along x2)"},
           {"N", "number of boundary segments along the arc (disc, half disc, ring)"},
           {"centre", "centre of the disc or ring: x,y; of the ball: x,y,z (default the origin)",
            "0,0"},
           {"center", "old spelling of centre"},
           {"r_in", "inner radius of the ring"},
           {"r_out", "outer radius of the ring"},
           {"layers", "number of element layers across the ring"},
           {"lx", "width of the rectangle or box, side of the square"},
           {"ly", "height of the rectangle, depth of the box"},
           {"lz", "height of the box"},
           {"h", "mesh size of the 3D shapes (tetrahedra)"},
           {"nx", "number of segments along x"},
           {"ny", "number of segments along y"},
           {"refs", "boundary references of the rectangle or square: bottom,right,top,left",
            "3,4,2,1"},
           {"pattern",
            "rectangle, square: alternating (two triangles per cell, alternating diagonals) | "
            "union-jack (four triangles around the cell centre)",
            "alternating"},
           {"grading",
            "growth of the mesh size per unit distance from the contact boundary (0: uniform); "
            "half-ball: from its pole",
            "0"},
           {"cap",
            "half-ball: the largest mesh size of the graded mesh (default R / 4, at least h)"},
           {"arcs",
            "disc: uniform (N/4 segments on every quarter) | graded (N/4 on the bottom quarter, "
            "the others sized by the grading: fine only near contact)",
            "uniform"},
           {"gamma1_above",
            "vertices with y above this value get the Gamma1 (Dirichlet) reference"},
           {"gamma3_below", "vertices with y below this value get the Gamma3 (contact) reference"},
       }},
      {"MATERIAL",
       true,
       "constitutive law of one sub-domain",
       {
           {"region", "sub-domain number (1-based, as in the mesh file)"},
           {"law",
            "hooke | svk | ciarlet-geymonat | kelvin-voigt (5.1): viscosity eta1, eta2 plus "
            "Hooke's E, nu, plus the MEMORY cards' kernel",
            "hooke"},
           {"E", "Young's modulus (hooke, svk, kelvin-voigt)"},
           {"nu", "Poisson's ratio, -1 < nu < 0.5 (hooke, svk, kelvin-voigt)"},
           {"eta1", "kelvin-voigt: viscosity coefficient of tr(eps') I (thesis mu1), >= 0", "0"},
           {"eta2", "kelvin-voigt: viscosity coefficient of eps' (thesis mu2), >= 0", "0"},
           {"c1", "ciarlet-geymonat: coefficient of I1 - 3, > 0"},
           {"c2", "ciarlet-geymonat: coefficient of I2 - 3, >= 0"},
           {"a", "ciarlet-geymonat: coefficient of I3 - 1, >= 0"},
           {"plane", "strain | stress (2D reduction: F33 = 1, or F33 from sigma33 = 0)", "strain"},
           {"thickness", "out-of-plane thickness, > 0", "1"},
           {"rho", "mass density, >= 0 (dynamic problems need rho > 0)", "0"},
       }},
      {"MEMORY",
       true,
       "one exponential term exp(-beta t) KK of the memory kernel K of a kelvin-voigt law (5.1), "
       "integrated by the trapezoidal rule (5.60)-(5.61); none: K = 0",
       {
           {"region", "sub-domain numbers (law=kelvin-voigt); default every sub-domain"},
           {"E", "Young's modulus of the isotropic tensor KK, > 0"},
           {"nu", "Poisson's ratio of KK, -1 < nu < 0.5"},
           {"beta", "decay rate of exp(-beta t), > 0 (1 / time)"},
       }},
      {"DIRICHLET",
       true,
       "prescribed displacement on the vertices and edges of a boundary reference",
       {
           {"ref", "boundary reference number"},
           {"ux", "prescribed horizontal displacement (omit to leave it free)"},
           {"uy", "prescribed vertical displacement (omit to leave it free)"},
           {"uz", "prescribed displacement along x3, in a 3D deck (omit to leave it free)"},
       }},
      {"TRACTION",
       true,
       "surface force per unit length on a boundary reference",
       {
           {"ref", "boundary reference number"},
           {"f", "traction vector: fx,fy"},
           {"ramp", "time t1 > 0 of a load growing linearly: value x t / t1 (TIME decks); default "
                    "constant"},
       }},
      {"PRESSURE",
       true,
       "normal pressure on a boundary reference (positive pushes into the body)",
       {
           {"ref", "boundary reference number"},
           {"p", "pressure"},
           {"ramp", "time t1 > 0 of a load growing linearly: value x t / t1 (TIME decks); default "
                    "constant"},
       }},
      {"BODYFORCE",
       true,
       "volume force on a sub-domain",
       {
           {"region", "sub-domain number"},
           {"f", "force per unit volume: fx,fy"},
           {"ramp", "time t1 > 0 of a load growing linearly: value x t / t1 (TIME decks); default "
                    "constant"},
       }},
      {"MOVINGLOAD",
       true,
       "a vertical Gaussian traction moving along x1 (the moving mass of ch. 6, (6.91)): "
       "(0, -F exp(-psi (x1 - x0 - c t)^2)) on the edges of a boundary reference; a static deck "
       "(no TIME card) takes it at t = 0",
       {
           {"ref", "boundary reference number"},
           {"F", "peak traction (GPa in the thesis's units)"},
           {"psi", "decay of the Gaussian, > 0, per unit length squared (m^-2; the thesis prints "
                   "m^-1)"},
           {"c", "speed of the load's centre along x1 (m/s)"},
           {"x0", "x1 of the load's centre at t = 0", "0"},
       }},
      {"CONTACT",
       false,
       "contact of a boundary reference (Gamma3) with a rigid obstacle: node-to-rigid elements "
       "with their normal law (penetration q_n = u_n - d beyond the obstacle surface, d the "
       "initial gap from the mesh)",
       {
           {"ref", "boundary reference of the contact zone"},
           {"obstacle", "plane | disc (2D) | sphere (3D, a rigid ball) | cylinder (3D, a rigid "
                        "circular cylinder, infinite along its axis: a wheel, a roller)"},
           {"point", "a point of the obstacle plane: x,y (x,y,z in 3D)"},
           {"normal", "outward unit normal of the obstacle: nx,ny (nx,ny,nz in 3D)"},
           {"centre", "disc or sphere obstacle: centre x,y (x,y,z in 3D); cylinder: a point of "
                      "its axis x,y,z"},
           {"axis", "cylinder obstacle: direction of its axis ax,ay,az (normalized)"},
           {"radius", "disc, sphere or cylinder obstacle: radius"},
           {"law",
            "signorini (1.22) | compliance (1.24): pressure cn [q_n]+, truncated at c3 | "
            "compliance-unilateral (1.26): compliance while q_n < g, a rigid wall at q_n = g | "
            "damped (1.25): pressure cn [v_n]+ of the normal velocity v_n | damped-unilateral "
            "(1.28): damped while v_n < g, the bound v_n <= g beyond (the laws in velocity need "
            "TIME scheme=quasistatic) | compliance-bilateral: pressure cn q_n on both sides, "
            "springs that also pull (a frictionless test law, no truncation)",
            "signorini"},
           {"cn", "compliance: pressure per unit penetration (GPa/m in the thesis's units), > 0; "
                  "damped laws: pressure per unit normal velocity (GPa s/m)"},
           {"c3", "compliance: truncation pressure min(cn [q_n]+, c3) of ch. 6, > 0; default "
                  "none"},
           {"g",
            "depth of the rigid wall beyond the obstacle surface, >= 0: signorini's extra gap, "
            "compliance-unilateral's layer, ipm's allowed penetration (sig-march); "
            "damped-unilateral: the bound on the normal velocity",
            "0"},
           {"exclude", "boundary references whose nodes get no contact element (e.g. the clamped "
                       "ends of Gamma3 on Gamma1), as a list"},
           {"gap", "old spelling of g"},
           {"strategy",
            "dynamic contact strategy of sig-march (a TIME deck only): signorini | "
            "compliance | specific-penalty | two-step | ipm",
            "signorini"},
           {"r", "foundation stiffness per unit area of compliance, specific-penalty and ipm "
                 "(sig-march), > 0"},
           {"persistency",
            "strategy=two-step: midpoint (the normal velocity of (3.39) at t_n, choice C15) | "
            "increment (q_n - q_{n-1}): what step (b) holds at zero",
            "midpoint"},
       }},
      {"FRICTION",
       false,
       "friction law of the contact boundary of a CONTACT card (slip q_t = t . u, t = (n2, -n1): "
       "+x1 on the foundation x2 <= 0; in 3D a vector of the node's tangent plane, its components "
       "along the tangents t1, t2 of the node's contact frame, the force in the disc of radius "
       "the bound)",
       {
           {"ref", "boundary reference of the CONTACT card"},
           {"law", "none | tresca (1.33): |T| <= threshold on every contact node | coulomb "
                   "(1.35): |T| <= mu N | nonmonotone (1.39): |T| <= mu(r) N, mu(r) = "
                   "(a - b) exp(-alpha r) + b, r the slip (or slip rate) magnitude, solved by "
                   "the convexification loop (4.110)-(4.112) | mu1, mu2 (8.3): |T| <= mu(q_n) N, "
                   "mu of the penetration q_n over the asperities' depth g of the CONTACT card: "
                   "mu1 rises from 0 to mu, mu2 falls from 2 mu to mu (sig-march)"},
           {"mu", "coulomb: friction coefficient, >= 0; mu1, mu2: mu0, the coefficient once the "
                  "asperities are crushed"},
           {"threshold", "tresca: slip bound, a traction (GPa in the thesis's units), >= 0"},
           {"bound",
            "coulomb, nonmonotone: normal: mu times the whole normal pressure N | compliance: "
            "mu times the compliance pressure p(min(q_n, g)) only, (4.6)/(5.6): on the wall "
            "Tresca's mu p(g)",
            "normal"},
           {"a", "nonmonotone: mu(0), >= b"},
           {"b", "nonmonotone: mu at large slip, >= 0"},
           {"alpha", "nonmonotone: decay of mu per unit slip, >= 0"},
           {"of",
            "nonmonotone: slip (the tangential displacement from the reference, ch. 4) | "
            "slip-rate (the tangential velocity: the marches in velocity, ch. 5 and 6)",
            "slip"},
       }},
      {"SOLVER",
       false,
       "linear backend and contact algorithm",
       {
           {"linear", "cholmod | umfpack | mumps: the sparse direct solver", "cholmod"},
           {"method", "linear | alm | penalty | pdas | projection; default pdas with a CONTACT "
                      "card, linear without"},
           {"r", "augmentation parameter (alm) or foundation stiffness (penalty), > 0", "100"},
           {"gamma", "parameter of the primal-dual active set test (3.20), > 0", "100"},
           {"c", "parameter of the iterative projection method (7.16), > 0", "100"},
           {"eps", "tolerance of stopping test (iv): relative increment and residual, > 0: of "
                   "the solve (sig-solve, default 1e-05), of each Newton phase of a time step "
                   "(sig-march, default 1e-10; the marches in velocity, TIME "
                   "scheme=backward-euler or quasistatic, take sig-solve's 1e-05)"},
           {"maxit", "maximum number of nonlinear iterations: of the solve (sig-solve, default "
                     "100), of each Newton phase of a time step (sig-march, default 50; the "
                     "marches in velocity take sig-solve's 100)"},
           {"search",
            "auto | yes | no: globalization of the contact Newton (modules/solver/NEWTON.md): "
            "auto and yes (the same) take steps that a merit and a cycle guard accept, for "
            "every method and bulk; no takes full steps, the thesis's algorithm, a cycle then "
            "ending the solve",
            "auto"},
           {"candidate_gap",
            "static small-strain solve: condense only the contact nodes whose initial gap is at "
            "most this length, > 0 (a 3D contact boundary has thousands of nodes, most far from "
            "the obstacle); a node outside that comes to touch widens the zone and the solve "
            "starts again, so the solution is the one without it; linear march (sig-march): "
            "only those nodes condensed, the others watched, a step that brings one of them "
            "through the obstacle stopping the march; default every contact node"},
       }},
      {"CONVEXIFICATION",
       false,
       "the convexification loop (4.110)-(4.112) of FRICTION law=nonmonotone in a static solve "
       "(sig-solve), or in every step of a march in velocity (sig-march scheme=backward-euler or "
       "quasistatic, of=slip-rate): "
       "mu frozen per node at the previous iterate's slip (rate), each convex problem solved by "
       "the SOLVER method",
       {
           {"eps",
            "outer tolerance of the thesis's test (l.7601): ||u(m+1) - u(m)||_V <= eps "
            "||u(m)||_V and the same for the contact tractions on Gamma3, > 0",
            "1e-5"},
           {"maxit", "maximum number of outer iterations (convex solves), >= 1", "200"},
           {"relaxation",
            "theta in (0, 1]: mu(m+1) = theta mu(slip(m+1)) + (1 - theta) mu(m); 1: none, as "
            "the thesis",
            "1"},
           {"start", "rest (u(0) = 0, mu = a) | slipped (mu = b, as after a long slip) | "
                     "previous (a march: mu of the previous step's slip rate, ALGORITHMS.md 3.3); "
                     "default rest in a static solve, previous in a march"},
       }},
      {"LOADSTEPS",
       false,
       "load stepping of the large-deformation solve (hyperelastic laws, sig-solve): the "
       "imposed displacements and loads grow in n equal steps, each solved by Newton",
       {
           {"n", "number of load steps, >= 1", "1"},
           {"start",
            "first iterate of the first load step: small-strain (the small-strain solution of "
            "that step's problem, contact included: the linearization at rest solved exactly) or "
            "rest (u = 0); a small-strain start that fails (its solve, every fraction of it "
            "inverting an element, or a tangent there that the backend cannot factorize) falls "
            "back to "
            "rest, with a warning",
            "small-strain"},
       }},
      {"TIME",
       false,
       "time marching (stage sig-march): elastodynamics (with a CONTACT card, by its strategy), "
       "the quasistatic viscoelastic march in velocity of ch. 5, or the viscoelastodynamic one "
       "of ch. 6",
       {
           {"scheme", "midpoint | newmark: implicit midpoint rule (3.39) or Newmark's average "
                      "acceleration; both conserve the discrete energy (8.33) without load | "
                      "quasistatic: backward Euler in velocity (5.62)-(5.64), no mass, contact "
                      "laws in velocity (law=damped, damped-unilateral) | backward-euler: backward "
                      "Euler in velocity with mass (6.63)-(6.66), (M/k + C + k K) w = ..., "
                      "contact laws of the displacement, friction of the slip rate"},
           {"T", "final time, > 0"},
           {"k", "time step, > 0; T / k must be a whole number of steps"},
           {"output_every", "keep the state every this many steps, >= 1", "1"},
           {"mass",
            "consistent | lumped | emm (Equivalent Mass Matrix (3.54), needs a CONTACT "
            "card, midpoint and newmark only); not for scheme=quasistatic",
            "consistent"},
           {"stress",
            "hyperelastic bodies: gonzalez (Gonzalez's algorithmic stress (3.41), exact energy "
            "balance) | midpoint (the midpoint configuration's stress, the contrast)",
            "gonzalez"},
       }},
      {"INITIAL",
       true,
       "uniform initial displacement and velocity of the whole body or of some sub-domains "
       "(a card sets only the fields it gives, a later card wins on shared nodes; Dirichlet dofs "
       "keep their imposed values)",
       {
           {"u", "initial displacement: ux,uy (3D: ux,uy,uz; default 0)"},
           {"v", "initial velocity: vx,vy (3D: vx,vy,vz; default 0)"},
           {"omega", "initial angular velocity (rad/s): 2D the rate counter-clockwise, adding "
                     "omega e3 x (X - centre) to the velocity; 3D the vector wx,wy,wz, adding "
                     "omega x (X - centre) (needs centre=)"},
           {"centre", "centre of the initial rotation: x,y (3D: x,y,z)"},
           {"region", "sub-domain numbers (1-based); default every sub-domain"},
       }},
      {"COMPARE",
       false,
       "analytic reference that sig-post compares the solution with (summary.json)",
       {
           {"analytic", "hertz: 2D Hertz contact of a half disc on a plane, thesis (7.38)"},
           {"R", "radius of the half disc"},
           {"f", "magnitude of the vertical traction on the top edge"},
           {"x0", "x1 of the centre line", "0"},
       }},
      {"OUTPUT",
       false,
       "what the post-processing stage writes",
       {
           {"vtk", "yes | no: write .vtu/.pvd files for ParaView", "yes"},
           {"name", "base name of the output files; default the datafile's stem"},
           {"compression",
            "zlib | lz4 | none: compression of the .vtu's arrays; zlib is read by every VTK XML "
            "reader (meshio included), lz4 writes a large mesh in half the time (ParaView and VTK "
            "8.1 on read it, meshio 5.0 does not)",
            "zlib"},
       }},
  };
  return schema;
}

const char* renamed_field(const std::string& keyword, const std::string& field) {
  // The old spellings the schema keeps readable ("old spelling of ..." in their help texts).
  struct Renamed {
    const char *keyword, *old_name, *name;
  };
  static constexpr Renamed renamed[] = {{"MESH", "center", "centre"}, {"CONTACT", "gap", "g"}};
  for (const Renamed& r : renamed)
    if (keyword == r.keyword && field == r.old_name) return r.name;
  return nullptr;
}

} // namespace sig
