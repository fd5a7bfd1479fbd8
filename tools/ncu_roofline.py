#!/usr/bin/env python3
"""Roofline positions from tools/ncu_roofline.sh's CSV files (Nsight Compute, --page raw): for each
profiled kernel, time, DRAM traffic and bandwidth, FLOP (FP32 and FP64: add + mul + 2 fma, from the
executed-instruction counts) and FLOP rate, arithmetic intensity, and the fraction of the H200's
peaks (HBM3e 4.8 TB/s, FP32 67 TFLOP/s, FP64 34 TFLOP/s, NVIDIA's data sheet for the SXM part).
Usage: tools/ncu_roofline.py bench/results/ncu/*.csv  -> a markdown table on stdout."""
import csv
import os
import sys

PEAK_BYTES, PEAK_FP32, PEAK_FP64 = 4.8e12, 67e12, 34e12


def number(text):
    return float(text.replace(",", "")) if text.strip() else 0.0


def kernels(path):
    with open(path, newline="") as f:
        lines = [line for line in f if line.startswith('"')]  # the bench's own output is interleaved
    rows = list(csv.reader(lines))
    header, units = rows[0], rows[1]
    for r in rows[2:]:
        d = dict(zip(header, r))
        u = dict(zip(header, units))
        t = number(d["gpu__time_duration.sum"]) * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}.get(u["gpu__time_duration.sum"], 1e-9)
        scale = {"byte": 1, "Kbyte": 1e3, "Mbyte": 1e6, "Gbyte": 1e9}.get(u["dram__bytes.sum"], 1)
        dram = number(d["dram__bytes.sum"]) * scale
        op = lambda k: number(d["smsp__sass_thread_inst_executed_op_%s_pred_on.sum" % k])
        fp32 = op("fadd") + op("fmul") + 2 * op("ffma")
        fp64 = op("dadd") + op("dmul") + 2 * op("dfma")
        name = d["Kernel Name"].split("<", 1)[1].split(",")[0].split("<")[0] if "<" in d["Kernel Name"] else d["Kernel Name"]
        yield {"case": os.path.basename(path)[4:-4], "kernel": name, "time": t, "dram": dram, "fp32": fp32, "fp64": fp64,
               "registers": d["launch__registers_per_thread"], "warps": number(d["sm__warps_active.avg.pct_of_peak_sustained_active"]),
               "sm": number(d["sm__throughput.avg.pct_of_peak_sustained_elapsed"])}


def main():
    print("| case | kernel | ms | DRAM GB | GB/s (% of 4.8 TB/s) | GFLOP/s (% of FP32 peak) | FLOP/byte | registers | active warps % | SM busy % |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for path in sys.argv[1:]:
        for k in kernels(path):
            flops = k["fp32"] + k["fp64"]
            rate = flops / k["time"]
            peak = PEAK_FP32 if k["fp32"] >= k["fp64"] else PEAK_FP64
            bw = k["dram"] / k["time"]
            print(f"| {k['case']} | {k['kernel']} | {1e3 * k['time']:.3f} | {k['dram'] / 1e9:.2f} | {bw / 1e9:.0f} ({100 * bw / PEAK_BYTES:.0f}%) | "
                  f"{rate / 1e9:.0f} ({100 * rate / peak:.1f}%) | {flops / max(k['dram'], 1):.1f} | {k['registers']} | {k['warps']:.0f} | {k['sm']:.0f} |")


if __name__ == "__main__":
    main()
