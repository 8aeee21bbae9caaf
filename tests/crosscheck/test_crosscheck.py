"""The cross-check of issue 7: each case of fixtures/crosscheck/cases.json agrees with every
reference that can build it (manifold3d, OpenVDB, OpenSCAD) and with its exact values, within
the tolerances of docs/crosscheck.md, or the disagreement is explained in the case list with
evidence that holds (solidkit matches the exact value, the reference does not). The report is
target/crosscheck/report.md (and .json)."""
import subprocess
import sys

import pytest

from xcheck import cases, paths
from xcheck.cases import REFERENCES

CASES = cases.load()
# The kinds of case issue 7 asks for, each by a case name prefix.
REQUIRED = ["sphere_minus_cube", "tricylinder_cube", "torus", "nested_shells", "menger_1", "menger_2",
            "menger_3", "gyroid_ball", "metaballs5", "platonic_tetrahedron", "platonic_cube",
            "platonic_octahedron", "platonic_dodecahedron", "platonic_icosahedron",
            "compound_tetrahedron", "compound_cube", "compound_dodecahedron", "swept_tube",
            "revolved_vase", "heightfield", "obj_in_csg", "tangent_spheres", "thin_plate"]


def test_case_list_covers_the_issue():
    names = {c["name"] for c in CASES}
    assert len(CASES) >= 25
    assert not [n for n in REQUIRED if n not in names]
    examples = sorted(p.relative_to(paths.ROOT).as_posix() for p in (paths.ROOT / "fixtures" / "examples").iterdir()
                      if p.suffix in (".json", ".rhai", ".csg"))
    sources = {c["source"] for c in CASES}
    assert [e for e in examples if e not in sources] == [], "every fixtures/examples model is a case"


def test_exact_values_reproduce():
    """fixtures/crosscheck/exact.json and the generated trees are what make_cases.py makes."""
    r = subprocess.run([sys.executable, str(paths.FIXTURES / "make_cases.py"), "--check"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def test_every_reference_builds_cases(crosscheck):
    """Each reference built most cases (a broken installation must not pass silently)."""
    for ref in REFERENCES:
        ok = [n for n, r in crosscheck["results"].items() if r.get(ref, {}).get("status") == "ok"]
        assert len(ok) >= len(crosscheck["results"]) // 2, f"{ref} built only {len(ok)} cases"


@pytest.mark.parametrize("name", [c["name"] for c in CASES])
def test_case(name, crosscheck):
    verdicts = {v["case"]: v for v in crosscheck["verdicts"]}
    if name not in verdicts:
        pytest.skip("not selected (CROSSCHECK_CASES)")
    v = verdicts[name]
    if v.get("known_bug"):
        # A recorded solidkit bug: expected to fail until fixed, and flagged once it passes so
        # that the entry gets removed (a strict xfail).
        assert not v["ok"], f"{name} passes now: remove its known_bug entry from cases.json"
        pytest.xfail(f"known solidkit bug: {v['known_bug']}")
    lines = [f"{c['system']} / {c['metric']}: {c['message']}"
             + (f" [explanation rejected: {'; '.join(c['evidence_problems'])}]" if c.get("evidence_problems") else "")
             for c in v["failing"]]
    assert v["ok"], f"{name} disagrees (see {paths.out_dir() / 'report.md'}):\n" + "\n".join(lines)
