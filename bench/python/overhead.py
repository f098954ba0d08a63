"""Issue 28's figures for the Python module, measured (not a test):
- the overhead of an `evaluate` whose result is cached (goal: at most 1 ms);
- reading a 1024 x 1024 channel as numpy (goal: no copy, under 50 us).

    PYTHONPATH=build/python python3 bench/python/overhead.py
Prints one line per figure: median and 10th-90th percentiles over many calls.
"""
import os
import statistics
import tempfile
import time

import numpy as np

import darkroom as dr


def timed(fn, count):
    samples = []
    for _ in range(count):
        t0 = time.perf_counter_ns()
        fn()
        samples.append((time.perf_counter_ns() - t0) / 1000.0)
    samples.sort()
    return statistics.median(samples), samples[len(samples) // 10], samples[len(samples) * 9 // 10]


def main():
    folder = tempfile.mkdtemp()
    value = np.random.default_rng(1).random((1024, 1024), dtype=np.float32)
    dr.Image.from_arrays({"value": value, "Z": value}).save(os.path.join(folder, "big.exr"))
    p = dr.Pipeline()
    read = p.add("ImageReader", path=os.path.join(folder, "big.exr"))
    colour = p.add("ColorMapping", channel="value", colormap="viridis")
    p.connect(read.image, colour.image)
    image = p.evaluate(colour.image)
    assert p.last_run
    p.evaluate(colour.image)
    assert p.last_run == [], "the second evaluation should come from the cache"
    med, lo, hi = timed(lambda: p.evaluate(colour.image), 2000)
    print(f"cached evaluate of a 1024 x 1024 pipeline: median {med:.1f} us (p10 {lo:.1f}, p90 {hi:.1f}); goal <= 1000 us")
    first = image["R"].__array_interface__["data"][0]
    assert all(image["R"].__array_interface__["data"][0] == first for _ in range(10)), "a channel was copied"
    med, lo, hi = timed(lambda: image["R"], 20000)
    print(f"1024 x 1024 channel as a numpy view: median {med:.2f} us (p10 {lo:.2f}, p90 {hi:.2f}); no copy "
          f"(same address every time); goal < 50 us")
    med, lo, hi = timed(lambda: np.array(image["R"]), 200)
    print(f"for scale, copying that channel with numpy: median {med:.0f} us")


if __name__ == "__main__":
    main()
