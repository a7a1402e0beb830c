#!/usr/bin/env python3
"""Merges runs of the bench group "mix" and prints the table of docs/PERFORMANCE.md.

    python3 bench/mix_table.py OUT.csv RUN1.csv RUN2.csv RUN3.csv > table.md

Each RUN is the --csv output of `prox_bench --quick --repeats 5 --filter mix/`. OUT.csv receives, per
case, the median over the runs of mean_ns, median_ns and p99_ns and the largest err_max (the other
columns from the last run), and OUT.txt (OUT.csv with .txt) the same rows as space-separated text; stdout receives one markdown row per pair type: the share that overlaps,
prox's mean distance time on shapes and on prepared solids, FCL's, and the two ratios; prox's signed
mean on shapes and on solids (the solids' p99), the solids' mean on the overlapping pairs alone, FCL's
signed mean and the two ratios, Coal's and Bullet's means, and the worst error over S of prox (any of
its four rows), FCL distance, FCL signed, Coal and Bullet.
"""
import csv
import statistics
import sys


def read(path):
    with open(path, newline="") as f:
        return {row["case"]: row for row in csv.DictReader(f)}


def num(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return None


def merge(runs):
    merged = {}
    for case, last in runs[-1].items():
        row = dict(last)
        rows = [r[case] for r in runs if case in r]
        for col in ("mean_ns", "median_ns", "p99_ns"):
            vals = [v for v in (num(r[col]) for r in rows) if v is not None]
            if vals:
                row[col] = "%.2f" % statistics.median(vals)
        errs = [v for v in (num(r["err_max"]) for r in rows) if v is not None]
        if errs:
            row["err_max"] = "%.3g" % max(errs)
        merged[case] = row
    return merged


def t(ns):
    if ns is None:
        return "–"
    return "%.0f ns" % ns if ns < 1000 else "%.2g µs" % (ns / 1000) if ns < 10000 else "%.0f µs" % (ns / 1000)


def ratio(a, b):
    if a is None or b is None or b == 0:
        return "–"
    r = a / b
    return "<0.01" if r < 0.01 else "%.2f" % r


def err(x):
    if x is None:
        return "–"
    return "0" if x == 0 else "%.0e" % x


def table(m):
    fams = []
    for case in m:
        fam = case.split("/")[1]
        if fam not in fams:
            fams.append(fam)
    print("| pair | overlap | prox distance: shape / solid | FCL distance | ratio: shape / solid "
          "| prox signed: shape / solid (solid p99) | solid signed, overlapping | FCL signed | ratio: shape / solid "
          "| Coal signed | Bullet | worst error: prox / FCL dist / FCL signed / Coal / Bullet |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for fam in fams:
        def get(method, col="mean_ns", subset="all"):
            row = m.get("mix/%s/%s/%s" % (fam, method, subset))
            return num(row[col]) if row else None
        note = m["mix/%s/prox/distance/all" % fam]["note"]
        over = [kv.split("=")[1] for kv in note.split(";") if kv.startswith("overlapping=")][0]
        pd, qd, fd = get("prox/distance"), get("prox-solid/distance"), get("fcl/distance")
        ps, qs, fs = get("prox/signed"), get("prox-solid/signed"), get("fcl/signed")
        own = [e for e in (get(k, "err_max") for k in ("prox/distance", "prox/signed", "prox-solid/distance",
                                                        "prox-solid/signed")) if e is not None]
        errs = [max(own) if own else None] + [get(k, "err_max") for k in ("fcl/distance", "fcl/signed", "coal/signed",
                                                                        "bullet/gjk-epa")]
        print("| %s | %s | %s / %s | %s | %s / %s | %s / %s (%s) | %s | %s | %s / %s | %s | %s | %s |" % (
            fam, over, t(pd), t(qd), t(fd), ratio(pd, fd), ratio(qd, fd), t(ps), t(qs),
            t(get("prox-solid/signed", "p99_ns")), t(get("prox-solid/signed", subset="overlap")), t(fs),
            ratio(ps, fs), ratio(qs, fs), t(get("coal/signed")), t(get("bullet/gjk-epa")),
            " / ".join(err(e) for e in errs)))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    runs = [read(p) for p in sys.argv[2:]]
    m = merge(runs)
    with open(sys.argv[1], "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(next(iter(runs[-1].values())).keys()))
        w.writeheader()
        for row in m.values():
            w.writerow(row)
    with open(sys.argv[1][:-4] + ".txt" if sys.argv[1].endswith(".csv") else sys.argv[1] + ".txt", "w") as f:
        f.write("# prox_bench --quick --repeats 5 --filter mix/, %d runs merged by bench/mix_table.py: per case the median of "
                "the runs' mean, median and p99 and the largest of their err_max; the other columns from the last run\n"
                % len(runs))
        cols = ["case", "n", "mean_ns", "median_ns", "p99_ns", "err_max", "err_p99", "wit_max", "mismatches", "note"]
        f.write("case n mean_ns median_ns p99_ns err_max err_p99 wit_max mism note\n")
        for row in m.values():
            f.write(" ".join(row[c] if row[c] != "" else "nan" for c in cols) + "\n")
    table(m)


if __name__ == "__main__":
    main()
