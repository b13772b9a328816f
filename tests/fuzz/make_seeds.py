#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora (tests/fuzz/corpus/NAME/) from the project's own test
data: the demo sidecar and the contract's example, the first lines of the committed recordings,
the bundled HMD profiles, the report descriptors of tests/xr/input/hid_test_data.h and the HID
reports of recordings/hid_*.vdrec.jsonl. Run from the repository root after those change; the output is
committed, so CI does not need Python."""
import json
import pathlib
import re
import shutil

root = pathlib.Path(__file__).resolve().parents[2]
corpus = root / "tests" / "fuzz" / "corpus"


def fresh(name):
    d = corpus / name
    shutil.rmtree(d, ignore_errors=True)
    d.mkdir(parents=True)
    return d


# Sidecars: the demo, the contract's example, and a per-effect override with the extension.
d = fresh("sidecar")
shutil.copy(root / "app" / "demo" / "interior.vdfx.json", d / "demo.vdfx.json")
example = {
    "format": "vdfx.sidecar", "version": 1,
    "video": {"path": "clip.mp4", "fps": 30.0, "frames": 900, "width": 3840, "height": 1920},
    "interpolation": {"exponent": 1.0, "time_scale": 1.0},
    "effects": [{"type": "exposure", "keyframes": [
        {"azimuth_deg": 30.0, "altitude_deg": 0.0, "frame": 75, "params": {"stops": 1.0}}]}]}
(d / "contract.vdfx.json").write_text(json.dumps(example, indent=2) + "\n")
example["effects"] = [{"type": "tint",
                       "interpolation": {"exponent": 1.5, "time_scale": 2.0, "distance": "geodesic"},
                       "keyframes": [{"azimuth_deg": -90.0, "altitude_deg": 45.0, "frame": 0,
                                      "params": {"gain": [1.0, 0.5, 2.0]}},
                                     {"azimuth_deg": 180.0, "altitude_deg": -90.0, "frame": 899,
                                      "params": {"gain": [0.0, 4.0, 1.0]}}]},
                      {"type": "vignette", "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 90.0,
                       "frame": 10, "params": {"radius_deg": 40.0, "falloff_deg": 0.01}}]}]
(d / "override.vdfx.json").write_text(json.dumps(example) + "\n")
# The extension types (docs/sidecar.md): flares of each light form, grains of each style.
kf = {"azimuth_deg": 20.0, "altitude_deg": 10.0, "frame": 5}
example["effects"] = [
    {"type": "flare", "style": "headset", "light": {"azimuth_deg": 40.0, "altitude_deg": 20.0},
     "settings": {"fade_deg": 20.0, "rings": 3},
     "keyframes": [dict(kf, params={"intensity": 2.0})]},
    {"type": "flare", "style": "directional",
     "light": [{"frame": 0, "azimuth_deg": -30.0, "altitude_deg": 5.0},
               {"frame": 800, "azimuth_deg": 60.0, "altitude_deg": 30.0}],
     "interpolation": {"exponent": 2.0, "time_scale": 0.5},
     "keyframes": [dict(kf, params={"intensity": 0.5}), {"azimuth_deg": -100.0, "altitude_deg": 0.0,
                                                          "frame": 600, "params": {"intensity": 4.0}}]},
    {"type": "flare", "style": "headset", "light": "auto", "keyframes": []}]
(d / "flare.vdfx.json").write_text(json.dumps(example) + "\n")
example["effects"] = [
    {"type": "grain", "style": "headset", "seed": 7, "settings": {"refresh_ms": 40.0},
     "keyframes": [dict(kf, params={"intensity": 0.5, "size": 1.0})]},
    {"type": "grain", "style": "object_cloud", "seed": 9007199254740993,
     "settings": {"count": 500, "shell": 2.0},
     "interpolation": {"exponent": 1.5, "time_scale": 3.0},
     "keyframes": [dict(kf, params={"intensity": 1.0, "size": 0.25}),
                   {"azimuth_deg": 170.0, "altitude_deg": -60.0, "frame": 899,
                    "params": {"intensity": 0.0, "size": 4.0}}]},
    {"type": "grain", "style": "free_cloud", "seed": 0, "settings": {"radius_m": 1.0},
     "keyframes": []}]
(d / "grain.vdfx.json").write_text(json.dumps(example) + "\n")

# Recordings: the header and the first lines of each committed one (kept small for the fuzzer).
d = fresh("recording")
for rec in sorted((root / "recordings").glob("*.vdrec.jsonl")):
    lines = rec.read_text().splitlines(keepends=True)[:6]
    (d / rec.name).write_text("".join(lines))

# HMD profiles: the bundled ones.
d = fresh("hmd_profile")
for p in sorted((root / "xr" / "headset" / "profiles").glob("*.json")):
    shutil.copy(p, d / p.name)

# Report descriptors: every byte table of the HID test data.
d = fresh("hid_descriptor")
header = (root / "tests" / "xr" / "input" / "hid_test_data.h").read_text()
descriptors = {}
for name, body in re.findall(r"std::vector<std::uint8_t> (k\w+Descriptor\w*) = \{(.*?)\};", header, re.S):
    body = re.sub(r"//[^\n]*", "", body)
    descriptors[name] = bytes(int(x, 16) for x in re.findall(r"0x[0-9A-Fa-f]{2}", body))
    (d / (name + ".bin")).write_bytes(descriptors[name])

# HID reports: selector byte (0 DS4, 1 DualSense, 2 SpaceMouse, 3 generic + its descriptor),
# then the reports of the matching recording, each preceded by its length.
d = fresh("hid_reports")
for selector, rec in [(0, "hid_ds4"), (1, "hid_dualsense"), (2, "hid_spacemouse"), (3, "hid_generic_gamepad")]:
    out = bytearray([selector])
    reports = []
    for line in (root / "recordings" / (rec + ".vdrec.jsonl")).read_text().splitlines()[1:]:
        hid = json.loads(line).get("hid")
        if not hid:
            continue
        if "descriptor" in hid:
            desc = bytes.fromhex(hid["descriptor"])
            out += bytes([len(desc)]) + desc
        elif hid["report"]:
            reports.append(bytes.fromhex(hid["report"]))
    for r in reports[:8]:
        out += bytes([len(r)]) + r
    (d / (rec + ".bin")).write_bytes(bytes(out))
