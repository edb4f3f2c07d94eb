#!/usr/bin/env python3
"""Denoise time of strahl's network against Intel Open Image Denoise's oidnDenoise, on the same
files, alternating: ROUNDS times (default 5) DenoiseTime (the network with the Vector API: its
first denoise in the JVM, then 3 runs after 2 untimed) and oidnDenoise (-n 5, the first run dropped as its warm-up), both on all
processors. Prints the medians of the wall time per denoise (min, max) and of the CPU time per
denoise (the JVM's process CPU time; for oidnDenoise the CPU time of a run of -n 5 less that of
-n 1, over 4: loading and set-up left out), per megapixel, and the load average.

    mvn -B -q -DskipTests package
    python3 docs/bench/denoise_time.py COLOR.pfm ALBEDO.pfm NORMAL.pfm [ROUNDS]

oidnDenoise: on the PATH, else the one `pip install pyoidn` ships (pyoidn/oidn/bin).
"""
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile


def oidn_tool():
    tool = shutil.which("oidnDenoise")
    if tool:
        return tool
    import pyoidn
    return os.path.join(os.path.dirname(pyoidn.__file__), "oidn", "bin", "oidnDenoise")


def cpu_of(cmd):
    """Runs cmd; returns (stdout + stderr, user + system CPU seconds of the process)."""
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    out = p.stdout.read()
    _, status, usage = os.wait4(p.pid, 0)
    if status != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), out))
    return out, usage.ru_utime + usage.ru_stime


def main():
    color, albedo, normal = sys.argv[1:4]
    rounds = int(sys.argv[4]) if len(sys.argv) > 4 else 5
    with open(color, "rb") as f:
        f.readline()
        w, h = map(int, f.readline().split())
    mpix = w * h / 1e6
    tool = oidn_tool()
    java = ["java", "--add-modules", "jdk.incubator.vector", "-cp", "target/strahl.jar", "docs/bench/DenoiseTime.java", "files",
            color, albedo, normal, "3"]
    net_wall, net_cpu, oidn_wall, oidn_cpu, loads, first_wall, first_cpu = [], [], [], [], [], [], []
    out_file = os.path.join(tempfile.mkdtemp(), "out.pfm")
    oidn = [tool, "-d", "cpu", "--hdr", color, "--alb", albedo, "--nrm", normal, "-o", out_file, "-v", "2"]
    for r in range(rounds):
        out, _ = cpu_of(java)
        m = re.search(r"median ([0-9.]+) s, min ([0-9.]+) s, max ([0-9.]+) s", out)
        net_wall += [float(m.group(2)), float(m.group(1)), float(m.group(3))]      # of 3 runs: all three
        net_cpu.append(float(re.search(r"per denoise: median ([0-9.]+) s", out).group(1)))
        loads.append(float(re.search(r"load average ([0-9.]+)", out).group(1)))
        m = re.search(r"first denoise in this JVM: ([0-9.]+) s, CPU ([0-9.]+) s", out)
        first_wall.append(float(m.group(1)))
        first_cpu.append(float(m.group(2)))
        out, cpu5 = cpu_of(oidn + ["-n", "5"])
        runs = [float(x) / 1000 for x in re.findall(r"Denoising\s+msec=([0-9.]+)", out)]
        oidn_wall += runs[1:]
        _, cpu1 = cpu_of(oidn + ["-n", "1"])
        oidn_cpu.append((cpu5 - cpu1) / 4)
        print("round %d: network %s s (CPU %.3f s), oidnDenoise %s s (CPU %.3f s), load %.1f" % (
            r + 1, " ".join("%.3f" % x for x in net_wall[-3:]), net_cpu[-1], " ".join("%.3f" % x for x in runs[1:]), oidn_cpu[-1],
            loads[-1]), flush=True)
    for name, wall, cpu in (("strahl's network", net_wall, net_cpu), ("oidnDenoise", oidn_wall, oidn_cpu)):
        print("%s, %dx%d: wall median %.3f s (min %.3f, max %.3f; %d runs) = %.2f s/Mpixel; CPU median %.3f s (min %.3f, max %.3f)"
              " = %.2f CPU-s/Mpixel" % (name, w, h, statistics.median(wall), min(wall), max(wall), len(wall), statistics.median(wall) / mpix,
                                         statistics.median(cpu), min(cpu), max(cpu), statistics.median(cpu) / mpix))
    print("strahl's network, its first denoise in a JVM (weights read, code compiled): wall median %.3f s (min %.3f, max %.3f),"
          " CPU median %.3f s (min %.3f, max %.3f)" % (statistics.median(first_wall), min(first_wall), max(first_wall),
                                                       statistics.median(first_cpu), min(first_cpu), max(first_cpu)))
    print("load average during the rounds: %.1f to %.1f on %d processors" % (min(loads), max(loads), os.cpu_count()))


if __name__ == "__main__":
    main()
