"""A mill study's files (study_mill: DIR/power.csv, one row per revolution; DIR/manifest.txt,
"key = value" lines), for the scripts that turn a run into its table (tools/los_bronces.sh,
tools/scaling_mill.sh)."""
import csv


def load(d):
    """(rows of power.csv as dicts, the manifest as a dict) of the run in folder d."""
    rows = list(csv.DictReader(open(d + "/power.csv")))
    m = {}
    for line in open(d + "/manifest.txt"):
        if " = " in line:
            k, v = line.rstrip("\n").split(" = ", 1)
            m[k.strip()] = v.strip()
    return rows, m
