#!/usr/bin/env python3
"""test_race.py BUILD_DIR CLRT PEER SCENE...: runs race.py --peer PEER on tiny images (32x32, few
samples) of the scenes and checks the record: its shape, that the references of both renderers
agree in every scene (with Cycles: the units check of point and area lights, the plane, spheres
and the depth cap), and that every figure is a positive finite number. Exit 77 (skipped), as
race.py, when the peer is not installed (install_cycles.sh or install_mitsuba.sh)."""
import json
import math
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import checks  # noqa: E402


def main():
    if len(sys.argv) < 5:
        sys.exit("usage: test_race.py BUILD_DIR CLRT PEER SCENE...")
    build, clrt, peer, scenes = pathlib.Path(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4:]
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp) / "race.json"
        command = [sys.executable, str(HERE / "race.py"), *scenes, "--peer", peer, "--build", str(build), "--clrt", clrt,
                   "--resolution", "32x32", "--spp", "4,16", "--seeds", "2", "--runs", "1",
                   "--ref-spp", "1024", "--json", str(out)]
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        print("\n".join(l for l in done.stdout.splitlines() if not l.startswith(("Fra:", "Saved:", "Time:"))))
        if done.returncode == 77:
            return 77
        if done.returncode != 0:
            print(f"FAIL: race.py exited with {done.returncode}")
            return 1
        record = json.loads(out.read_text())
    check = checks.Checks()

    for key in ("machine", "peer", "versions", "settings", "scenes"):
        check(key in record, f"the record has no `{key}`")
    check(record["machine"]["cores"] >= 1 and len(record["machine"]["load_before"]) == 3
          and len(record["machine"]["load_after"]) == 3 and record["machine"]["cpu"], "machine")
    check(record["peer"]["name"] == peer and record["peer"]["version"] and record["versions"]["clrt_commit"],
          "peer and versions")
    check([s["scene"] for s in record["scenes"]] == scenes, "one entry per scene, in order")
    for s in record["scenes"]:
        name = s["scene"]
        check(s.get("references_agree") is True, f"{name}: the references disagree: {s.get('reference_mean_difference_rgb')}")
        check(all(abs(d) <= 0.01 for d in s.get("reference_mean_difference_rgb", [1])), f"{name}: mean difference")
        check([r["spp"] for r in s.get("spp", [])] == [4, 16], f"{name}: rows for 4 and 16 spp")
        for r in s.get("spp", []):
            for key in ("clrt_rmse", "peer_rmse", "clrt_rmse_vs_own_ref", "peer_rmse_vs_own_ref", "clrt_rmse_vs_peer_ref", "peer_rmse_vs_clrt_ref", "rmse_ratio",
                        "clrt_s", "peer_render_s", "peer_process_s", "clrt_efficiency",
                        "peer_efficiency_render", "peer_efficiency_process", "speedup_vs_render",
                        "speedup_vs_process"):
                v = r.get(key)
                check(isinstance(v, float) and math.isfinite(v) and v > 0, f"{name} {r['spp']} spp: {key} = {v}")
            check(len(r["rmse_per_seed"]["clrt"]) == 2 and len(r["times"]["peer"]) == 2, f"{name}: seeds and runs")
            check(r["peer_process_s"] > r["peer_render_s"], f"{name}: the process outlasts its render call")
        rows = s.get("spp", [])
        if len(rows) == 2:
            # More samples, less noise, for both.
            check(rows[1]["clrt_rmse"] < rows[0]["clrt_rmse"], f"{name}: clrt's RMSE falls with spp")
            check(rows[1]["peer_rmse"] < rows[0]["peer_rmse"], f"{name}: {peer}'s RMSE falls with spp")
    return check.report()


if __name__ == "__main__":
    sys.exit(main())
