"""The case list, fixtures/crosscheck/cases.json: each case once (its source, resolution, exact
values with how they were obtained, per-system settings, systems it skips and why, and the
recorded explanations of known disagreements with their evidence)."""
import json
import re

from . import paths

SYSTEMS = ["solidkit", "manifold3d", "openvdb", "openscad"]
REFERENCES = SYSTEMS[1:]


EXPECT = re.compile(r"expect:\s*shells=(\d+)\s+genus=(\d+)")


def _expected_topology(source) -> dict:
    """shells and genus from an example's `expect: shells=N genus=G` line."""
    m = EXPECT.search(source.read_text()) if source.exists() else None
    if not m:
        return {}
    return {"shells": int(m.group(1)), "genus": int(m.group(2)),
            "how": "the example's own 'expect:' line"}


def load() -> list:
    doc = json.loads(paths.CASES_FILE.read_text())
    exact = json.loads((paths.FIXTURES / "exact.json").read_text())
    cases = doc["cases"]
    for c in cases:
        e = _expected_topology(paths.ROOT / c["source"])
        more = exact.get(c["name"], {})
        if e and more.get("how"):
            more = {**more, "how": more["how"] + "; topology: " + e["how"]}
        c["exact"] = {**e, **more, **c.get("exact", {})}
    names = [c["name"] for c in cases]
    if len(set(names)) != len(names):
        raise ValueError("duplicate case names in cases.json")
    return cases


def by_name(name: str) -> dict:
    for c in load():
        if c["name"] == name:
            return c
    raise KeyError(name)
