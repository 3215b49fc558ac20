"""Four-bar facts by hand, nothing of algkin: the Grashof class from the four lengths."""


def hand_grashof(a, d, l, m):
    """The textbook rule: s + L against p + q, and which link is the shortest."""
    bars = {"crank": a, "ground": d, "coupler": l, "rocker": m}
    ordered = sorted(bars.values())
    margin = ordered[1] + ordered[2] - ordered[0] - ordered[-1]
    if margin < 0:
        return "triple-rocker"
    if margin == 0:
        return "change-point"
    return {"crank": "crank-rocker", "ground": "double-crank", "coupler": "double-rocker",
            "rocker": "rocker-crank"}[min(bars, key=bars.get)]
