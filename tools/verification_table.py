#!/usr/bin/env python3
"""Renders verification/README.md: the template with @TABLE@ replaced by the suite's rows and
@WORK_PRECISION@ by the work-precision study's tables (results/work_precision_*.md beside the tsv files).

Usage: verification_table.py TEMPLATE RESULTS.tsv [RESULTS.tsv ...] > README.md
Each results file is what one run of the suite wrote through BLAZE_REPORT (verification/report.hpp):
case, quantity, thesis, limit, measured, pass/FAIL, backend, source. Its file name (cpu,
nvidia-h200, ...) becomes the column header of its measured values.
"""
import glob
import os
import sys


def cell(text):
    """A markdown table cell: a '|' inside (absolute values) would end the cell."""
    return text.replace("|", "\\|")


def main():
    template, results = sys.argv[1], sys.argv[2:]
    columns, rows, order = [], {}, []
    for path in results:
        name = os.path.splitext(os.path.basename(path))[0]
        columns.append(name)
        with open(path, encoding="utf-8") as f:
            for line in f:
                fields = line.rstrip("\n").split("\t")
                if len(fields) != 8:
                    continue
                case, quantity, thesis, limit, measured, status, _backend, source = fields
                key = (case, quantity)
                if key not in rows:
                    rows[key] = {"thesis": thesis, "limit": limit, "source": source, "measured": {}}
                    order.append(key)
                rows[key]["measured"][name] = measured if status == "pass" else f"**{measured} FAIL**"
    header = "| case | check | thesis | limit | " + " | ".join(columns) + " | reference |"
    rule = "|" + "---|" * (5 + len(columns))
    lines = [header, rule]
    last_case = None
    for case, quantity in order:
        r = rows[(case, quantity)]
        shown = case if case != last_case else ""
        last_case = case
        measured = " | ".join(cell(r["measured"].get(c, "-")) for c in columns)
        fields = [cell(shown), cell(quantity), cell(r["thesis"]), cell(r["limit"]), measured, cell(r["source"])]
        lines.append("| " + " | ".join(fields) + " |")
    with open(template, encoding="utf-8") as f:
        text = f.read()
    parts = []
    for md in sorted(glob.glob(os.path.join(os.path.dirname(results[0]) if results else ".", "work_precision_*.md"))):
        with open(md, encoding="utf-8") as f:
            parts.append(f.read().strip())
    work = "\n\n".join(parts) if parts else "(not run yet: `make fig-work-precision`)"
    sys.stdout.write(text.replace("@TABLE@", "\n".join(lines)).replace("@WORK_PRECISION@", work))


if __name__ == "__main__":
    main()
