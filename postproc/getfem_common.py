"""What the GetFEM comparison scripts (getfem_hertz.py, getfem_ring.py, getfem_friction.py) share:
their command line's checks and a quiet GetFEM, a deck's cards (through the report library's
deck reader), the version of Debian's python3-getfem, gmsh meshes (the half disc, the half ball of
getfem_hertz3d.py) and their import into GetFEM, isotropic elasticity as a GetFEM model (plane
strain in 2D, 3D), the node coordinates of sig-mesh's case.nopo, the nodal weights of the contact
nodes (lengths on a polyline, areas on a surface) and the timed solves."""
import json
import math
import subprocess
import time

import numpy as np

from sigreport import Deck


def deck_cards(path):
    """{KEYWORD: {field: value}} of a datafile (sigreport.Deck; the first card of each keyword;
    names and values lower case, as the stages read their choices case-insensitively)."""
    cards = {}
    for card in Deck.read(path).cards():
        cards.setdefault(card.keyword, {k: v.lower() for k, v in card.fields.items()})
    return cards


def parse_timed_args(parser, fail):
    """The arguments of a script that times its solves (--repeat, >= 1, else fail(message)),
    with GetFEM's assembly traces and minor warnings silenced: they would bury the summary line."""
    import getfem as gf  # only the scripts that run GetFEM need it
    args = parser.parse_args()
    if args.repeat < 1:
        fail("--repeat must be >= 1")
    gf.util_trace_level(0)
    gf.util_warning_level(1)
    return args


def print_summary(summary, line, path=None):
    """Print the summary line of a solve and write the summary as JSON at path (if given); the
    line's "{solve}" becomes the timed solves' seconds and their median."""
    times = ", ".join(f"{t:.3f}" for t in summary["solve_seconds"])
    median = summary["solve_seconds_median"]
    print(line.replace("{solve}", f"solve {times} s (median {median:.3f})"))
    if path:
        path.write_text(json.dumps(summary, indent=1) + "\n")


def getfem_version():
    try:
        return subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "python3-getfem"],
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "5.4 (version not found)"


def gmsh_mesh(geo, msh, dim, numbers, fmt="msh22"):
    """gmsh GEO meshed in dimension dim with `-setnumber NAME VALUE` for each of `numbers` (a dict),
    written to msh in format fmt (msh22 for GetFEM's importer); returns msh. Raises RuntimeError
    with gmsh's output when it fails."""
    cmd = ["gmsh", str(geo), f"-{dim}", "-format", fmt, "-v", "2"]
    for name, value in numbers.items():
        cmd += ["-setnumber", name, repr(value)]
    cmd += ["-o", str(msh)]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0 or not msh.is_file():
        raise RuntimeError(f"gmsh failed ({' '.join(cmd)}):\n{done.stdout}{done.stderr}")
    return msh


def import_gmsh(msh, regions):
    """The gmsh mesh msh imported by GetFEM; RuntimeError when it lacks one of the physical
    `regions`."""
    import getfem as gf  # only the scripts that run GetFEM need it
    m = gf.Mesh("import", "gmsh", str(msh))
    found = set(int(r) for r in np.atleast_1d(m.regions()))
    if not set(regions) <= found:
        raise RuntimeError(f"{msh}: GetFEM imported regions {sorted(found)}, expected "
                           f"{' and '.join(str(r) for r in regions)}")
    return m


def gmsh_half_disc(geo, workdir, R, n, grading):
    """meshes/half_disc.geo meshed by gmsh as sig-mesh's half-disc generator does (N uniform
    segments on the arc, the same grading), written as msh 2.2 for GetFEM's importer; returns the
    path. Raises RuntimeError with gmsh's output when it fails."""
    return gmsh_mesh(geo, workdir / f"half_disc_N{n}.msh", 2, {"R": R, "N": n, "grading": grading})


def import_half_disc(geo, workdir, R, n, grading, regions):
    """gmsh_half_disc's mesh imported by GetFEM, and the .msh path; RuntimeError with gmsh's
    output, or when GetFEM's mesh lacks one of the physical `regions`."""
    msh = gmsh_half_disc(geo, workdir, R, n, grading)
    return import_gmsh(msh, regions), msh


def isotropic_elasticity(m, E, nu, integration):
    """GetFEM's isotropic linearized elasticity with the 3D Lame coefficients of E, nu on the P1
    vector field u of the mesh m (dimension m.dim(): plane strain in 2D), integrated by
    `integration` (e.g. "IM_TRIANGLE(2)"). Returns (model with the variable "u", its MeshFem, its
    MeshIm)."""
    import getfem as gf  # only the scripts that run GetFEM need it
    mfu = gf.MeshFem(m, m.dim())
    mfu.set_classical_fem(1)
    mim = gf.MeshIm(m, gf.Integ(integration))
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("lambda", [E * nu / ((1 + nu) * (1 - 2 * nu))])
    md.add_initialized_data("mu", [E / (2 * (1 + nu))])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
    return md, mfu, mim


def explicit_model(K, size):
    """A GetFEM model of one variable "U" of `size` unknowns whose leading block is the matrix K
    (an elastic model's tangent, GetFEM's Spmat) and the rest unknowns of their own (the extra
    unknowns z of the Tresca construction): the basic contact bricks then act on U."""
    import getfem as gf  # only the scripts that run GetFEM need it
    nbdof = int(K.size()[0])
    md = gf.Model("real")
    md.add_variable("U", size)
    Kx = gf.Spmat("empty", size, size)
    Kx.assign(list(range(nbdof)), list(range(nbdof)), K)
    md.add_explicit_matrix("U", "U", Kx, 1, 0)
    return md


def plane_strain_elasticity(m, E, nu, traction, region):
    """Our P1 plane-strain elasticity on the GetFEM mesh m: GetFEM's 2D isotropic linearized
    elasticity with the 3D Lame coefficients, the traction (a pair) on the boundary `region`.
    Returns (model with the variable "u", its MeshFem, its MeshIm)."""
    md, mfu, mim = isotropic_elasticity(m, E, nu, "IM_TRIANGLE(2)")
    md.add_initialized_data("F", list(traction))
    md.add_source_term_brick(mim, "u", "F", region)
    return md, mfu, mim


def nopo_coordinates(path):
    """Node coordinates (NP x NDIM numpy array, mesh order) of a case.nopo written by sig-mesh: a
    NOPO file of Fortran sequential records (4-byte markers) in the 8-byte-integer, 8-byte-real
    variant, each array NOP0, NOP1, NOP2, NOP4, NOP5 one record opening with its word count.
    NOP2 gives NDIM (word 1) and NP (word 22), NOP4 the coordinates. Raises ValueError when the
    file is not in that layout."""
    data = path.read_bytes()
    records, pos = [], 0
    while pos + 4 <= len(data):
        size = int.from_bytes(data[pos:pos + 4], "little", signed=True)
        end = pos + 4 + size
        if size < 8 or end + 4 > len(data) or data[end:end + 4] != data[pos:pos + 4]:
            raise ValueError(f"{path}: record at byte {pos} is not a Fortran record")
        records.append(data[pos + 4:end])
        pos = end + 4
    if len(records) < 4:
        raise ValueError(f"{path}: {len(records)} records, a NOPO file has NOP0 NOP1 NOP2 NOP4 NOP5")
    words = [np.frombuffer(r, "<i8") for r in records[:3]]
    for name, w, r in zip(("NOP0", "NOP1", "NOP2"), words, records):
        if len(r) % 8 or w[0] != len(r) // 8 - 1:
            raise ValueError(f"{path}: {name} is not an 8-byte record opening with its length")
    ndim, npoints = int(words[2][1]), int(words[2][22])
    nop4 = records[3]
    if int(np.frombuffer(nop4[:8], "<i8")[0]) != ndim * npoints or len(nop4) != 8 * (1 + ndim * npoints):
        raise ValueError(f"{path}: NOP4 does not hold NDIM x NP = {ndim} x {npoints} reals")
    return np.frombuffer(nop4[8:], "<f8").reshape(npoints, ndim).copy()


def tributary_lengths(points):
    """Half the chords to the neighbours along a polyline (points 2 x n, in order): the nodal
    weights of sig-contact's node-to-rigid elements."""
    chord = np.linalg.norm(np.diff(points, axis=1), axis=0)
    w = np.zeros(points.shape[1])
    w[:-1] += chord / 2
    w[1:] += chord / 2
    return w


def tributary_areas(mim, region):
    """Nodal weights of the P1 nodes on the boundary `region` of mim's mesh: the integral of each
    node's P1 hat function over the region's faces, i.e. one third of the area of each surface
    triangle to each of its vertices (exact: the integration of mim is exact for P1). Returns
    (coordinates dim x n, weights n) of the region's nodes, in increasing scalar P1 dof."""
    import getfem as gf  # only the scripts that run GetFEM need it
    mf = gf.MeshFem(mim.linked_mesh(), 1)
    mf.set_classical_fem(1)
    weights = gf.asm_generic(mim, 1, "Test_w", region, "w", 1, mf, np.zeros(mf.nbdof()))
    dofs = np.sort(mf.basic_dof_on_region(region))
    return mf.basic_dof_nodes()[:, dofs], np.asarray(weights)[dofs]


def timed_solves(md, unknowns, options, repeat):
    """One untimed md.solve (GetFEM assembles its linear bricks once and keeps them), then
    `repeat` timed ones, each from the same start (unknowns: {variable: value}). Returns
    (seconds of each timed md.solve alone, Newton iterations of each, all converged)."""
    def solve():
        for name, value in unknowns.items():
            md.set_variable(name, value)
        t0 = time.perf_counter()
        result = np.atleast_1d(md.solve(*options))
        seconds = time.perf_counter() - t0
        return seconds, int(result[0]), bool(result[1]) if len(result) > 1 else True

    solve()
    runs = [solve() for _ in range(repeat)]
    return [r[0] for r in runs], [r[1] for r in runs], all(r[2] for r in runs)


def snap_arc(points, ids, center, R, angle0, segments, step):
    """sig-mesh's snap_arc (modules/mesh/src/generators_gmsh.cpp): move the points `ids` (columns
    of the 2 x n array `points`, changed in place) of a gmsh arc to center + R (cos, sin)(angle0 +
    k step), k = 0..segments the nearest arc position, cos and sin set to exactly 0 below 1e-15
    (gmsh places arc nodes to about 1e-9 R). Raises ValueError unless the ids fill the positions
    one each."""
    if len(ids) != segments + 1:
        raise ValueError(f"{len(ids)} nodes on the arc, expected {segments + 1}")
    period = round(2 * math.pi / step)
    taken = set()
    for i in ids:
        angle = math.atan2(points[1, i] - center[1], points[0, i] - center[0])
        k = round((angle - angle0) / step) % period  # std::lround: halves away from zero, never hit
        if k > segments or k in taken:
            raise ValueError(f"point {i} is not at a free arc position")
        taken.add(k)
        c, s = math.cos(angle0 + k * step), math.sin(angle0 + k * step)
        points[0, i] = center[0] + R * (0.0 if abs(c) < 1e-15 else c)
        points[1, i] = center[1] + R * (0.0 if abs(s) < 1e-15 else s)
