#!/usr/bin/env python3
"""Stale objects of an updated map (issue #16 target "< 5 % stale"), for map_update_battery.sh.
   stale_objects.py M/objects.json Q/world/objects.json Q/changes.json "class,class,..."
An object of M (of the listed classes) is stale when it stands where the truth removed or moved an
object of its class (centre within 0.5 m of a true `before` box, the map metrics' half gate) and no
object of its class of the changed world Q/world is within 0.5 m of it: the old place kept.
Prints {"n_map": .., "n_stale": .., "fraction": ..}."""
import json
import math
import sys

R = 0.5
m_path, w_path, ch_path, classes = sys.argv[1:5]
keep = set(c.strip() for c in classes.split(","))


def objs(path):
    d = json.load(open(path))
    return [(o["class"], o["center_m"][:2]) for o in d["objects"] if o["class"] in keep]


def near(p, q):
    return math.hypot(p[0] - q[0], p[1] - q[1]) <= R


m, w = objs(m_path), objs(w_path)
old = [(c["class"], c["before"]["center_m"][:2]) for c in json.load(open(ch_path))["changes"]
       if c["kind"] in ("removed", "moved") and c["class"] in keep]
stale = sum(1 for cls, p in m
            if any(c == cls and near(p, q) for c, q in old) and not any(c == cls and near(p, q) for c, q in w))
print(json.dumps({"n_map": len(m), "n_stale": stale, "fraction": stale / len(m) if m else 0.0}))
