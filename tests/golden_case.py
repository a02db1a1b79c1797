#!/usr/bin/env python3
"""Golden-image cases of golden/spec.json.

  golden_case.py check CASE --binary PENUMBRA --out DIR   render CASE and compare with its golden
  golden_case.py update [CASE...] --binary PENUMBRA --out DIR
                                                          regenerate goldens, printing metrics
                                                          against the old ones
  golden_case.py list                                     the case names
  golden_case.py coverage --binary PENUMBRA               fail unless every technique that
                                                          `penumbra techniques` lists has a case
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SPEC = os.path.join(ROOT, "golden", "spec.json")


def load_cases():
    with open(SPEC, encoding="utf-8") as f:
        spec = json.load(f)
    defaults = spec.get("defaults", {})
    cases = {}
    for c in spec["cases"]:
        merged = dict(defaults)
        merged.update(c)
        merged["tolerance"] = dict(defaults.get("tolerance", {}), **c.get("tolerance", {}))
        cases[c["name"]] = merged
    return cases


def render(binary, case, out_exr):
    w, h = case["size"]
    cmd = [binary, "render", os.path.join(ROOT, case["scene"]), "-t", case["technique"],
           "--size", f"{w}x{h}", "-f", str(case["frame"]), "-o", out_exr, "--quiet"]
    for key, value in case.get("overrides", {}).items():
        cmd += ["-D", f"{key}={json.dumps(value)}"]
    subprocess.run(cmd, check=True)


def compare(binary, case, ref, test, diff):
    tol = case["tolerance"]
    cmd = [binary, "compare", ref, test, "--channels", case["channels"], "--json",
           "--fail", str(tol["fail"]), "--failpercent", str(tol["fail_percent"]),
           "--warn", str(tol["fail"] / 2), "--diff", diff]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode > 2:
        raise SystemExit(f"compare failed ({r.returncode}): {r.stderr.strip()}")
    return r.returncode, json.loads(r.stdout)


def check(args):
    case = load_cases()[args.case]
    out = os.path.join(args.out, args.case)
    os.makedirs(out, exist_ok=True)
    test = os.path.join(out, "test.exr")
    golden = os.path.join(ROOT, "golden", f"{args.case}.exr")
    render(args.binary, case, test)
    code, metrics = compare(args.binary, case, golden, test, os.path.join(out, "diff.exr"))
    with open(os.path.join(out, "metrics.json"), "w", encoding="utf-8") as f:
        json.dump(metrics, f, indent=2)
    shadow = metrics.get("shadow_mae")
    limit = case["tolerance"]["shadow_mae"]
    print(f"{args.case}: verdict {metrics['verdict']}, mae {metrics['mae']:.6f}, "
          f"max {metrics['max']:.4f}, shadow_mae {shadow}, limit {limit}; files in {out}")
    if code == 2 or (shadow is not None and shadow > limit):
        print(f"FAIL: see {out}/test.exr, {out}/diff.exr and {out}/metrics.json")
        return 1
    return 0


def update(args):
    cases = load_cases()
    names = args.cases or sorted(cases)
    for name in names:
        if name not in cases:
            raise SystemExit(f"update-golden: unknown case '{name}' (known: {', '.join(sorted(cases))})")
    for name in names:
        case = cases[name]
        out = os.path.join(args.out, name)
        os.makedirs(out, exist_ok=True)
        test = os.path.join(out, "new.exr")
        golden = os.path.join(ROOT, "golden", f"{name}.exr")
        render(args.binary, case, test)
        if os.path.exists(golden):
            _, m = compare(args.binary, case, golden, test, os.path.join(out, "diff.exr"))
            print(f"{name}: against the old golden: mae {m['mae']:.6f}, max {m['max']:.4f} at "
                  f"({m['max_x']},{m['max_y']}) {m['max_channel']}, shadow_mae {m.get('shadow_mae')}")
        else:
            print(f"{name}: new case")
        shutil.copyfile(test, golden)
    return 0


def coverage(args):
    r = subprocess.run([args.binary, "techniques", "--json"], capture_output=True, text=True,
                       check=True)
    registered = [t["name"] for t in json.loads(r.stdout)]
    covered = {c["technique"] for c in load_cases().values()}
    missing = [t for t in registered if t not in covered]
    if missing:
        print(f"FAIL: no golden case in golden/spec.json for: {', '.join(missing)}")
        return 1
    print(f"every registered technique has a golden case: {', '.join(registered)}")
    return 0


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)
    c = sub.add_parser("check")
    c.add_argument("case")
    u = sub.add_parser("update")
    u.add_argument("cases", nargs="*")
    for s in (c, u):
        s.add_argument("--binary", required=True)
        s.add_argument("--out", required=True)
    sub.add_parser("list")
    cov = sub.add_parser("coverage")
    cov.add_argument("--binary", required=True)
    args = p.parse_args()
    if args.command == "list":
        print("\n".join(sorted(load_cases())))
        return 0
    if args.command == "coverage":
        return coverage(args)
    return check(args) if args.command == "check" else update(args)


if __name__ == "__main__":
    sys.exit(main())
