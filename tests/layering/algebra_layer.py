#!/usr/bin/env python3
"""The algebra stays algebra (DESIGN.md: the stage layer).

    algebra_layer.py ROOT [--links LIBRARY=DEP,DEP,... ...]

The algebra libraries, solver and integrator, may see the core, the contact laws and the algebra
below them (the integrator the solver, the solver not the integrator), nothing else: no mesh, no
assembly, no material, no contact element, no post-processing and nothing of the stage layer
(modules/stages), which builds their bulks and problems from the DS files.

Two checks:
 1. Includes. Every header and source under modules/solver and modules/integrator, and every
    project header they reach through their #include "..." lines (followed transitively, so that
    a core or contact-law header that pulled in the mesh would count), must belong to an allowed
    library. A header is found as modules/<module>/include/<path> (the contact laws:
    modules/contact/laws/include/<path>) or beside the including file.
 2. Links. With --links (CMake passes each library's LINK_LIBRARIES), the libraries the algebra
    links, followed transitively through the project's libraries, must be allowed ones; outside
    packages (Eigen, SuiteSparse, MUMPS, ...) are not the project's and pass.

Prints each violation with the chain of includes or links that reaches it; exit 1 if any.
"""
import argparse
import re
import sys
from pathlib import Path

# What each algebra library may include and link, by library name (sig_<name> in CMake).
ALLOWED = {
    "solver": {"core", "contact_laws", "solver"},
    "integrator": {"core", "contact_laws", "solver", "integrator"},
}
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]+"([^"]+)"', re.MULTILINE)
SOURCES = ("*.hpp", "*.cpp")


def library_of(path, modules):
    """The library a file under modules/ belongs to: the module, or contact_laws."""
    parts = path.relative_to(modules).parts
    if parts[:2] == ("contact", "laws"):
        return "contact_laws"
    return parts[0]


def include_roots(modules):
    """Every project include directory: modules/*/include and modules/contact/laws/include."""
    return sorted(modules.glob("*/include")) + sorted(modules.glob("*/laws/include"))


def resolve(name, including, roots):
    """The project file that #include "name" in `including` reaches, or None."""
    for folder in [including.parent] + roots:
        candidate = folder / name
        if candidate.is_file():
            return candidate.resolve()
    return None


def include_violations(root):
    """The violations, and the number of files read (the algebra's and the headers reached)."""
    modules = (root / "modules").resolve()
    roots = include_roots(modules)
    violations = []
    read = set()
    for algebra, allowed in ALLOWED.items():
        starts = [f.resolve() for pattern in SOURCES for f in (modules / algebra).rglob(pattern)]
        if not starts:
            violations.append(f"{algebra}: no source under {modules / algebra}")
        # Breadth-first over the include graph, remembering how each file was reached.
        reached_by = {f: None for f in starts}
        queue = list(starts)
        while queue:
            current = queue.pop(0)
            for line_number, name in includes_of(current):
                target = resolve(name, current, roots)
                where = f"{current.relative_to(root)}:{line_number}"
                if target is None:
                    violations.append(f'{algebra}: {where} includes "{name}", which is no '
                                      f"project header (include it by its module path)")
                    continue
                library = library_of(target, modules)
                if library not in allowed:
                    chain = " <- ".join(
                        str(f.relative_to(root)) for f in path_to(current, reached_by))
                    violations.append(f'{algebra}: {where} includes "{name}" of the {library} '
                                      f"library (reached from {chain})")
                    continue
                if target not in reached_by:
                    reached_by[target] = current
                    queue.append(target)
        read.update(reached_by)
    return violations, len(read)


def includes_of(path):
    text = path.read_text(encoding="utf-8", errors="replace")
    for match in INCLUDE.finditer(text):
        yield text.count("\n", 0, match.start()) + 1, match.group(1)


def path_to(file, reached_by):
    chain = []
    while file is not None:
        chain.append(file)
        file = reached_by[file]
    return chain


def link_violations(links):
    """links: library -> the targets it links (sig_* are ours, the rest outside packages)."""
    violations = []
    for algebra, allowed in ALLOWED.items():
        if algebra not in links:
            violations.append(f"{algebra}: no --links given for it")
            continue
        reached_by = {algebra: None}
        queue = [algebra]
        while queue:
            library = queue.pop(0)
            for target in links.get(library, []):
                if not target.startswith("sig_"):
                    continue
                dependency = target[len("sig_"):]
                if dependency not in allowed:
                    chain = " <- ".join(path_to(library, reached_by))
                    violations.append(f"{algebra}: sig_{library} links {target} (reached from "
                                      f"{chain})")
                elif dependency not in reached_by:
                    reached_by[dependency] = library
                    queue.append(dependency)
    return violations


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", type=Path, help="the source tree")
    parser.add_argument("--links", action="append", default=[], metavar="LIBRARY=DEP,DEP",
                        help="a project library (without sig_) and what it links")
    args = parser.parse_args()
    links = {}
    for entry in args.links:
        library, _, dependencies = entry.partition("=")
        links[library.removeprefix("sig_")] = [d for d in dependencies.split(",") if d]
    violations, read = include_violations(args.root.resolve())
    if args.links:
        violations += link_violations(links)
    for v in violations:
        print(f"FAIL: {v}")
    if violations:
        print(f"algebra_layer: {len(violations)} violation(s); the algebra (solver, integrator) "
              "may include and link only the core, the contact laws and the algebra below it; "
              "what reads meshes, assembled systems, materials or contact elements belongs to "
              "modules/stages")
        return 1
    print(f"algebra_layer: ok, {read} files read (the solver's, the integrator's and the headers "
          f"they reach) include only {sorted(set().union(*ALLOWED.values()))}"
          + (", and link no other project library" if args.links else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
