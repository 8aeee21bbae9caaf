"""Judging one case: solidkit's mesh against itself (its JSON report against the measures of the
STL it wrote), against the exact values the case records, and against each reference (volume,
area, genus, shells, closed/manifold, Hausdorff) within the tolerances of tolerance.py.

A disagreement passes only when the case list records an explanation for it whose evidence
holds here: `{"system", "metric", "reason", "evidence": {"metric" (default: the same),
"exact" (must equal the case's exact value when it has one; otherwise give "how"), "matches"}}`
— the `matches` system (usually solidkit) agrees with the exact value within tolerance and the
explained system does not. Each disagreement's message says which system is closest to the
exact value when one is known."""
from . import tolerance
from .cases import REFERENCES, SYSTEMS

METRICS = ["volume", "area", "genus", "shells", "closed_manifold", "hausdorff"]


def value(result: dict, metric: str):
    if not result or result.get("status") != "ok":
        return None
    m = result["measures"]
    if metric == "closed_manifold":
        return bool(m["closed"] and m["manifold"])
    if metric == "hausdorff":
        h = result.get("hausdorff")
        return None if h is None else h["symmetric"]
    return m.get(metric)


def _g(r):
    return float(r.get("grid", 0.0) or 0.0)


def _e(r):
    return float(r.get("facet_error", 0.0) or 0.0)


def _fmt(metric, v):
    if v is None:
        return "n/a"
    if metric in ("volume", "area", "hausdorff"):
        return f"{v:.6g}"
    return str(v)


class Judge:
    def __init__(self, case: dict, results: dict):
        self.case = case
        self.results = results
        self.exact = dict(case.get("exact", {}))
        # every case is a solid: its exact boundary is a closed 2-manifold (tangent_spheres's
        # pinch point is resolved by two shells, see its case)
        self.exact.setdefault("closed_manifold", True)
        sk = results.get("solidkit", {})
        ok = sk.get("status") == "ok"
        self.area = self.exact.get("area") or (sk["measures"]["area"] if ok else None)
        self.volume = self.exact.get("volume") or (sk["measures"]["volume"] if ok else None)
        self.av = (self.area / abs(self.volume)) if self.area and self.volume else 0.0
        self.diagonal = sk.get("diagonal") or 1.0

    # -- tolerances -----------------------------------------------------------------------------
    def tol(self, metric: str, a: dict, b: dict):
        """Tolerance between systems a and b (b = {} for the exact value), in the metric's units
        (relative for volume and area, model units for Hausdorff, None: must be equal)."""
        ga, gb, ea, eb = _g(a), _g(b), _e(a), _e(b)
        if metric == "volume":
            return tolerance.volume_tol(self.av, ga, gb, ea, eb)
        if metric == "area":
            return tolerance.area_tol(self.av, ga, gb, ea, eb)
        if metric == "hausdorff":
            return tolerance.hausdorff_tol(ga, gb, ea, eb)
        return None

    def agree(self, metric, va, vb, tol):
        if metric == "hausdorff":
            return va is not None and va <= tol
        if va is None or vb is None:
            return False
        if metric in ("volume", "area"):
            return abs(va - vb) <= tol * abs(vb)
        return va == vb

    def diff_text(self, metric, va, vb, tol):
        if metric in ("volume", "area") and va is not None and vb:
            return f"{(va - vb) / abs(vb):+.3%} (tolerance ±{tol:.3%})"
        if metric == "hausdorff" and va is not None:
            return f"{va / self.diagonal:.3%} of the diagonal (tolerance {tol / self.diagonal:.3%})"
        return ""

    def closest(self, metric) -> str:
        """Which systems are closest to the exact value of `metric`, with each one's error."""
        if metric not in self.exact:
            return "no exact value known"
        x = self.exact[metric]
        errs = []
        for s in SYSTEMS:
            v = value(self.results.get(s), metric)
            if v is None:
                continue
            if metric in ("volume", "area"):
                errs.append((abs(v - x) / abs(x), s, f"{s} {(v - x) / abs(x):+.3%}"))
            else:
                errs.append((0 if v == x else 1 + abs(v - x), s, f"{s} {v}"))
        if not errs:
            return f"exact {_fmt(metric, x)}"
        errs.sort()
        best = [s for e, s, _ in errs if e == errs[0][0]]
        how = ("the boundary of a solid" if metric == "closed_manifold"
               else self.exact.get("how", "see cases.json"))
        return (f"exact {_fmt(metric, x)} ({how}): closest "
                f"{' and '.join(best)}; " + ", ".join(t for _, _, t in errs))

    # -- checks ---------------------------------------------------------------------------------
    def checks(self) -> list:
        out = []
        sk = self.results.get("solidkit", {})
        if sk.get("status") != "ok":
            out.append(self._check("solidkit", "build", False, f"solidkit failed: {sk.get('reason')}"))
            return out
        m, own = sk["measures"], sk.get("own", {})
        # solidkit's own report against the STL it wrote (catches writer bugs)
        si = own.get("self_intersections")
        out.append(self._check("solidkit", "self_intersections", si in (0, None),
                               f"solidkit's mesh has {si} self-intersecting triangle pairs"))
        for k in ("closed", "manifold", "oriented", "genus", "shells"):
            ok = own.get(k) == m.get(k)
            out.append(self._check("solidkit", f"self_{k}", ok,
                                   f"solidkit reports {k} = {own.get(k)} but its STL measures {m.get(k)}"))
        vol_ok = abs(own.get("volume", 0) - m["volume"]) <= 1e-5 * abs(m["volume"])
        out.append(self._check("solidkit", "self_volume", vol_ok,
                               f"solidkit reports volume {own.get('volume')} but its STL measures {m['volume']}"))
        cm = value(sk, "closed_manifold")
        out.append(self._check("solidkit", "closed_manifold", cm,
                               f"solidkit's mesh is not a closed oriented 2-manifold: boundary edges "
                               f"{m['boundary_edges']}, non-manifold edges {m['non_manifold_edges']}, "
                               f"non-manifold vertices {m['non_manifold_vertices']}, inconsistent "
                               f"edges {m['inconsistent_edges']}"))
        # against exact values
        for metric in ("volume", "area", "genus", "shells"):
            if metric not in self.exact:
                continue
            v, x = value(sk, metric), self.exact[metric]
            tol = self.tol(metric, sk, {})
            ok = self.agree(metric, v, x, tol)
            out.append(self._check("exact", metric, ok,
                                   f"{metric}: solidkit {_fmt(metric, v)} vs exact {_fmt(metric, x)} "
                                   f"{self.diff_text(metric, v, x, tol)}; {self.closest(metric)}"))
        # against each reference
        for ref in REFERENCES:
            r = self.results.get(ref, {})
            st = r.get("status")
            if st == "skipped" or st is None:
                continue
            if st != "ok":
                out.append(self._check(ref, "build", False, f"{ref} failed: {r.get('reason')}"))
                continue
            for metric in METRICS:
                vs, vr = value(sk, metric), value(r, metric)
                tol = self.tol(metric, sk, r)
                if metric == "hausdorff":
                    ok = self.agree(metric, vr, None, tol) if vr is not None else False
                    msg = (f"Hausdorff distance solidkit–{ref} {_fmt(metric, vr)} = "
                           f"{self.diff_text(metric, vr, None, tol)}")
                else:
                    ok = self.agree(metric, vs, vr, tol)
                    msg = (f"{metric}: solidkit {_fmt(metric, vs)} vs {ref} {_fmt(metric, vr)} "
                           f"{self.diff_text(metric, vs, vr, tol)}; {self.closest(metric)}")
                out.append(self._check(ref, metric, ok, msg))
        return out

    def _check(self, system, metric, ok, message) -> dict:
        c = {"system": system, "metric": metric, "ok": bool(ok), "message": "" if ok else message}
        if not ok:
            c.update(self._explain(system, metric))
        return c

    def _explain(self, system, metric) -> dict:
        for ex in self.case.get("explained", []):
            if ex.get("system") != system or ex.get("metric") != metric:
                continue
            ev = ex.get("evidence", {})
            em = ev.get("metric", metric)
            x = ev.get("exact")
            problems = []
            if x is None:
                problems.append("the evidence gives no exact value")
            elif em in self.exact and self.exact[em] != x:
                problems.append(f"the evidence's exact {em} {x} is not the case's {self.exact[em]}")
            elif em not in self.exact and not ev.get("how"):
                problems.append("the evidence's exact value says not how it was obtained")
            matcher = self.results.get(ev.get("matches", "solidkit"), {})
            target = self.results.get(system, {}) if system != "exact" else {}
            if not problems:
                vm = value(matcher, em)
                tm = self.tol(em, matcher, {})
                if not self.agree(em, vm, x, tm):
                    problems.append(f"{ev.get('matches', 'solidkit')}'s {em} {_fmt(em, vm)} does not match "
                                    f"the exact {_fmt(em, x)}")
                if system != "exact":
                    vt = value(target, em)
                    tt = self.tol(em, target, {})
                    if vt is not None and self.agree(em, vt, x, tt):
                        problems.append(f"{system}'s {em} {_fmt(em, vt)} matches the exact value too")
            return {"explained": not problems, "explanation": ex.get("reason", ""),
                    "evidence_problems": problems}
        return {"explained": False}


def judge(case: dict, results: dict) -> dict:
    j = Judge(case, results)
    checks = j.checks()
    failing = [c for c in checks if not c["ok"] and not c.get("explained")]
    explained = [c for c in checks if not c["ok"] and c.get("explained")]
    used = {(c["system"], c["metric"]) for c in explained}
    stale = [e for e in case.get("explained", []) if (e.get("system"), e.get("metric")) not in
             {(c["system"], c["metric"]) for c in checks if not c["ok"]}]
    return {"case": case["name"], "checks": checks, "failing": failing, "explained": explained,
            "stale_explanations": stale, "ok": not failing, "explanations_used": sorted(used),
            "known_bug": case.get("known_bug")}
