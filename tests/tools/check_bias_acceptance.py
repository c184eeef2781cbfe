#!/usr/bin/python3
"""Acceptance of issue 12 on a `diptych sweep` results.json (docs/shadow-bias.md): constant bias
on shadow-sphere-sun, one map resolution, one sun elevation, amounts in increasing order.

Checks fractions and the crossing, never timings: the acne fraction starts above 40% and ends
below 1%; the amount where it first drops below 1% (log-interpolated) lies within a factor of 2
of the predicted (w/2) tan(theta), w and theta as the sweep measured them; and the
peter-panning fraction at the largest amount exceeds the one at the crossing.
"""
import json
import math
import sys


def main():
    points = json.load(open(sys.argv[1]))["points"]
    amounts = [p["params"]["constant_bias"] for p in points]
    acne = [p["signal"]["acne_rate"] for p in points]
    pp = [p["signal"]["peter_panning_rate"] for p in points]
    g = points[0]["geometry"]
    predicted = 0.5 * g["texel_world"] * math.tan(math.radians(g["incidence_deg"]))
    assert amounts == sorted(amounts), amounts
    assert acne[0] > 0.40, "acne at the smallest bias %.3f is not above 40%%" % acne[0]
    assert acne[-1] < 0.01, "acne at the largest bias %.4f is not below 1%%" % acne[-1]
    i = next(k for k, a in enumerate(acne) if a < 0.01)
    t = (acne[i - 1] - 0.01) / (acne[i - 1] - acne[i])
    cross = math.exp(math.log(amounts[i - 1]) + t * (math.log(amounts[i]) - math.log(amounts[i - 1])))
    ratio = cross / predicted
    assert 0.5 <= ratio <= 2.0, "crossing %.4g vs predicted %.4g (ratio %.2f)" % (cross, predicted, ratio)
    pp_at_cross = pp[i - 1] + t * (pp[i] - pp[i - 1])
    assert pp[-1] > pp_at_cross, "peter-panning does not grow past the threshold: %s" % pp
    print("acne %.1f%% -> %.2f%%; crossing %.4g world, predicted (w/2)tan(theta) = %.4g "
          "(w %.4g, theta %.1f deg), ratio %.2f; peter-panning %.2f%% at the crossing -> %.2f%%"
          % (100 * acne[0], 100 * acne[-1], cross, predicted, g["texel_world"], g["incidence_deg"],
             ratio, 100 * pp_at_cross, 100 * pp[-1]))


if __name__ == "__main__":
    main()
