#!/usr/bin/env python3
"""A notebook-style position sweep: step the stage along one axis, let it settle, and
read the grating (the measured position) and the following error at each point.
Prints CSV: point, commanded mm, measured mm (grating, averaged while settled), error um.

    python3 position_sweep.py --points 5 --step 0.5            # relative steps from where X is
    python3 position_sweep.py --home --start 10 --points 11    # absolute, after homing X

Run it with BenchPilot open (benchpilot, or benchpilot --api-socket PATH with --socket PATH).
"""
import argparse
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import benchpilot  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--socket", help="the GUI's API socket (default: %s)" % benchpilot.default_socket_path())
    ap.add_argument("--instrument", default="stage")
    ap.add_argument("--axis", default="X")
    ap.add_argument("--home", action="store_true", help="home the axis first; the sweep is then absolute from --start")
    ap.add_argument("--start", type=float, default=None, help="absolute start, mm (needs a homed axis)")
    ap.add_argument("--step", type=float, default=0.5, help="mm between points")
    ap.add_argument("--points", type=int, default=5)
    ap.add_argument("--settle-s", type=float, default=0.25, help="how long to read the grating at each point")
    args = ap.parse_args()

    inst, axis = args.instrument, args.axis
    with benchpilot.connect(args.socket, name="position sweep") as bp, bp.acquire():
        if args.home:
            bp.device.home(instrument=inst, axes=axis)
        positions = bp.subscribe({"positions": {"instrument": inst, "max_hz": 50}})
        latest = {}
        if args.start is not None:
            bp.device.move(instrument=inst, targets={axis: args.start})
        print("point,commanded_mm,measured_mm,following_error_um")
        for point in range(args.points):
            if point > 0 or args.start is None:
                # Waits until the axis is still, like benchpilot-cli move; the result is the status.
                bp.device.move(instrument=inst, targets={axis: args.step}, relative=True)
            readings = []
            until = time.monotonic() + args.settle_s
            while time.monotonic() < until:
                try:
                    msg = positions.get(timeout=max(0.01, until - time.monotonic()))
                except Exception:  # queue.Empty: the axis is still and nothing changed
                    continue
                latest.update(msg["data"])  # snapshot first, then only the axes that changed
                if axis in latest:
                    readings.append(latest[axis])
            status = bp.device.status(instrument=inst)["axes"][axis]
            measured = statistics.fmean(r["measured"] for r in readings) if readings else status["measured"]
            error = (measured - status["position"]) * 1000
            print("%d,%.4f,%.4f,%.2f" % (point, status["position"], measured, error), flush=True)
        positions.close()


if __name__ == "__main__":
    main()
