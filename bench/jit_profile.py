"""The report of bench/jit_profile.sh: perf's samples of one process charged to the disassembly
of llvmpipe's shader mapping. Arguments: the objdump listing, perf's instruction addresses (one
hex address a line), and the mapping's first and last address (hex).

It prints the share of all samples in the mapping; each function of it (llvmpipe calls its
texel-fetch routines, which follow the shader and end in ret); each loop of more than 1 000 bytes
(a backward jump: the pass's loops, the regeneration loop, the searches' pending-triangle loops)
with its calls; and how many per-lane loads the shader's main function holds: inline gathers (a
uniform-block read gallivm could not prove uniform, eight lanes each with a bounds check) and
storage-buffer lane loops (an eight-trip loop per component)."""
import collections
import re
import sys


def main():
    listing, ips_file, lo, hi = sys.argv[1], sys.argv[2], int(sys.argv[3], 16), int(sys.argv[4], 16)
    ips = collections.Counter(int(l, 16) for l in open(ips_file) if l.strip())
    total = sum(ips.values())
    inside = sum(v for a, v in ips.items() if lo <= a < hi)
    rows = []
    for line in open(listing):
        m = re.match(r"\s*([0-9a-f]+):\t([0-9a-f ]+)\t(.*)", line)
        if m:
            rows.append((int(m.group(1), 16), m.group(3).strip()))

    def share(a, b):
        return 100.0 * sum(v for x, v in ips.items() if a <= x < b) / max(inside, 1)

    print(f"samples: {total}, in the shader's mapping {100.0 * inside / max(total, 1):.1f} %, code {hi - lo} bytes")
    starts = [lo] + [a + 1 for a, t in rows if t.startswith("ret")]
    main_end = starts[1] if len(starts) > 1 else hi
    for a, b in zip(starts, starts[1:]):
        print(f"function {a:x}-{b:x}: {share(a, b):.1f} %")
    for a, t in rows:
        m = re.match(r"j\w+\s+0x([0-9a-f]+)", t)
        if m and int(m.group(1), 16) < a and a - int(m.group(1), 16) > 1000:
            start = int(m.group(1), 16)
            body = [u for x, u in rows if start <= x <= a]
            calls = sum(1 for u in body if u.startswith("call"))
            gathers, lane_loops = per_lane_loads(body)
            print(f"loop {start:x}-{a:x} ({a - start} bytes, {calls} calls, {gathers} inline gathers, "
                  f"{lane_loops} lane loops): {share(start, a + 1):.1f} %")
    gathers, lane_loops = per_lane_loads([t for a, t in rows if a < main_end])
    print(f"per-lane loads in the main function: {gathers} inline gathers, {lane_loops} storage-buffer lane loops")


def per_lane_loads(instructions):
    """Inline gathers (one vpinsrd of lane 1 from memory each) and eight-trip lane loops."""
    gathers = sum(1 for t in instructions if re.match(r"vpinsrd \$0x1,\(", t))
    lane_loops = sum(1 for t in instructions if re.match(r"cmp\s+\$0x8,%e", t))
    return gathers, lane_loops


if __name__ == "__main__":
    main()
