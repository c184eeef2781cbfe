#!/usr/bin/python3
"""Point and spot predictions of issue 12 on `diptych shadow-bias` summaries (docs/shadow-bias.md
§4), constant bias, --receiver ground.

usage: check_bias_lights.py spot SUMMARY.json | point SUMMARY.json

spot (perspective map): every curve crosses 1% acne where the per-pixel texel model says,
within a factor of 1.5, and the model's acne rate follows the measured one (largest gap under
5 points of percentage).
point (cube map, light overhead): the ground is normal to the -y face's axis, so the map's
axis depth is constant on it and the model predicts (nearly) no acne whatever the incidence;
the measured acne stays under 2% with no bias at all, where a distance-along-the-ray model would
say up to 50%.
Spot: ground pixels outside the cone are left out of the counts (unreached_pixels > 0); point:
none is (a point light reaches every pixel).
"""
import json
import sys


def curves(path):
    modes = json.load(open(path))["modes"]
    assert [m["mode"] for m in modes] == ["constant"], modes
    return modes[0]


def spot(path):
    m = curves(path)
    points = {p["index"]: p for p in m["points"]}
    for c in m["curves"]:
        measured, model = c["acne_crossing_1pct"], c["predicted_crossing_1pct"]
        assert c["max_acne_rate"] > 0.2, "no acne to start from: %s" % c
        assert measured > 0 and model, "no crossing: %s" % c
        ratio = measured / model
        assert 1 / 1.5 <= ratio <= 1.5, "crossing %.4g vs model %.4g" % (measured, model)
        gap = max(abs(points[i]["signal"]["acne_rate"] - points[i]["geometry"]["predicted_acne_rate"])
                  for i in c["indices"])
        assert gap < 0.05, "model and measurement differ by %.3f" % gap
        print("spot %d: acne < 1%% from %.4g, model %.4g (ratio %.2f), largest gap %.1f points" %
              (c["resolution"], measured, model, ratio, 100 * gap))
    # Ground pixels outside the cone get no light: they are no receivers of it (the exact side
    # traces no ray there), so a map's depth test there counts neither as acne nor as a shadow.
    unreached = {p["geometry"]["unreached_pixels"] for p in m["points"]}
    assert len(unreached) == 1 and unreached.pop() > 0, "no pixel left out of the cone: %s" % unreached


def point(path):
    m = curves(path)
    points = {p["index"]: p for p in m["points"]}
    for c in m["curves"]:
        first = points[c["indices"][0]]
        assert first["geometry"]["predicted_acne_rate"] < 0.02, first["geometry"]
        assert c["max_acne_rate"] < 0.02, "acne on the ground under a point light: %s" % c
        assert first["geometry"]["unreached_pixels"] == 0, "a point light reaches every pixel"
        print("point %d: model %.2f%%, measured at most %.2f%% acne" %
              (c["resolution"], 100 * first["geometry"]["predicted_acne_rate"],
               100 * c["max_acne_rate"]))


if __name__ == "__main__":
    {"spot": spot, "point": point}[sys.argv[1]](sys.argv[2])
