#!/usr/bin/env python3
"""Turns bench_passes JSON (--benchmark_out=FILE --benchmark_out_format=json)
into the markdown table of docs/performance.md."""
import json
import sys


def main(path):
    with open(path) as f:
        data = json.load(f)
    ctx = data["context"]
    print(f"Machine: {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz, "
          f"load average at start {', '.join(f'{x:.2f}' for x in ctx.get('load_avg', []))}; {ctx.get('date')}.")
    print()
    print("| benchmark | size | variant | ms | MP/s | CPU ms (all threads) | time / memcpy of the same bytes |")
    print("|---|---|---|---:|---:|---:|---:|")
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        parts = b["name"].split("/")
        name = parts[0].removeprefix("BM_")
        size = parts[1] if len(parts) > 1 else ""
        variant = b.get("label", "")
        # The median over iterations (pass_bench.cpp), not Google Benchmark's mean,
        # which one slow iteration on a shared machine can dominate.
        if "median_ms" in b:
            ms = b["median_ms"]
        else:
            ms = b["real_time"] if b.get("time_unit") == "ms" else b["real_time"] / 1e6
        cpu = f"{b['cpu_ms']:.1f}" if "cpu_ms" in b else ""
        print(f"| {name} | {size}² | {variant} | {ms:.1f} | {b['MP/s']:.1f} | {cpu} | {b['vs_memcpy']:.1f} |")


if __name__ == "__main__":
    main(sys.argv[1])
