#!/usr/bin/env python3
"""test_scenes.py BUILD_DIR: the scenes race.py writes itself, checked without a render:
knob4.ray (from clrt-make-scenes --family knob) has the knob's 576 spheres spread evenly over
the four natively mapped lobe subsets, each sphere under its own subset's material, a black
sky, one shadow ray from its area light, and the knob's camera, floor and light otherwise; and
writing it twice gives the same bytes."""
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import checks  # noqa: E402
import race  # noqa: E402


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: test_scenes.py BUILD_DIR")
    build = pathlib.Path(sys.argv[1])
    check = checks.Checks()

    scene = race.prepare_knob(build)
    first = scene.read_text(encoding="utf-8")
    check(race.prepare_knob(build).read_text(encoding="utf-8") == first, "knob4.ray: the same bytes every time")
    lines = first.splitlines()
    spheres = [i for i, line in enumerate(lines) if line.startswith("sphere ")]
    check(len(spheres) == 576, f"knob4.ray: {len(spheres)} spheres, not 576")
    with race.make_scenes(build, ["--family", "knob"]) as tmp:
        subsets = {s: race.knob_lines((pathlib.Path(tmp) / f"knob-lobes-{s}.ray").read_text(encoding="utf-8"))[1]
                   for s in race.KNOB_SUBSETS}
        knob_spheres = race.knob_lines((pathlib.Path(tmp) / "knob-lobes-d.ray").read_text(encoding="utf-8"))[2]
    materials = [lines[i - 1] for i in spheres]
    for subset, material in subsets.items():
        check(materials.count(material) == 144, f"knob4.ray: {materials.count(material)} spheres of `{subset}`, not 144")
    check([lines[i] for i in spheres] == knob_spheres, "knob4.ray: the knob's spheres, in its order")
    check("background 0 0 0" in lines, "knob4.ray: a black sky")
    lights = [line for line in lines if line.startswith("light ")]
    check(len(lights) == 1 and lights[0].endswith(" 1") and " area " in lights[0], f"knob4.ray: one area light of 1 sample: {lights}")
    return check.report()


if __name__ == "__main__":
    sys.exit(main())
