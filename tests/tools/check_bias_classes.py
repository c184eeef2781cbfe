#!/usr/bin/python3
"""Contact-based classes of issue 12 on `diptych sweep` results.json files (docs/shadow-bias.md
§3): constant bias, amounts in increasing order.

usage: check_bias_classes.py contact CONTACT_RESULTS.json  (contact-slab, --receiver ground)
       check_bias_classes.py room ROOM_RESULTS.json        (closed-room, every receiver)

contact: the slab's foot is found as contacts; no false light below the slab's thickness along
the light (0.1 / cos 30 = 0.115); past it, the ground's false light next to the foot is
peter-panning, growing with the bias, and none of it is a leak.
room: every interior pixel is exactly shadowed; past the roof's thickness along the light
(0.065) the false light is mostly leak (at least twice the peter-panning at the room's corners,
which are contacts too), and above 30% of the shadowed pixels at the largest bias.
"""
import json
import sys


def rows(path):
    points = json.load(open(path))["points"]
    amounts = [p["params"]["constant_bias"] for p in points]
    assert amounts == sorted(amounts), amounts
    return [(a, p["signal"]) for a, p in zip(amounts, points)]


def contact(path):
    r = rows(path)
    for b, s in r:
        assert s["contact_pixels"] > 20, "the slab's foot has no contacts: %s" % s
        assert s["light_leak"] <= 2, "leak on the ground next to the foot at b=%g: %s" % (b, s)
        if b < 0.1:
            assert s["peter_panning"] == 0, "false light below the slab thickness: b=%g %s" % (b, s)
    pp = [s["peter_panning_rate"] for b, s in r if b > 0.115]
    assert len(pp) >= 2 and pp[0] > 0.01, "no peter-panning past the thickness: %s" % pp
    assert pp == sorted(pp) and pp[-1] > 2 * pp[0], "peter-panning does not grow: %s" % pp
    print("contact: %d contact pixels; peter-panning %s past b = 0.115; leak 0" %
          (r[0][1]["contact_pixels"], ", ".join("%.1f%%" % (100 * v) for v in pp)))


def room(path):
    r = rows(path)
    for b, s in r:
        assert s["lit_outside"] == 0, "an interior pixel is exactly lit: %s" % s
        if b < 0.05:
            assert s["light_leak_rate"] + s["peter_panning_rate"] < 0.01, (b, s)
    b, s = r[-1]
    assert s["light_leak_rate"] > 0.30, "leak %.3f at b=%g" % (s["light_leak_rate"], b)
    assert s["light_leak"] >= 2 * s["peter_panning"], "leak is not the main class: %s" % s
    print("room: at b=%g leak %.1f%%, peter-panning %.1f%% (corners), %d contact pixels" %
          (b, 100 * s["light_leak_rate"], 100 * s["peter_panning_rate"], s["contact_pixels"]))


if __name__ == "__main__":
    {"contact": contact, "room": room}[sys.argv[1]](sys.argv[2])
