#!/usr/bin/env python3
"""A plate run followed by imaging: dispense a recipe on the analyzer, then plan and
run a stitching scan on the microscope stage, all while BenchPilot stays open (the
operator sees both jobs, and can take control back at any moment).

    python3 plate_then_scan.py --recipe resources/examples/reagent-transfer.recipe.json --out run1

Writes RUN/plate.run.jsonl (the recipe's run log: a stopped run resumes with
benchpilot-cli recipe run … --resume) and RUN/scan/ (the scan's log and exports:
TileConfiguration.txt, positions.pos, scan.csv).
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import benchpilot  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--socket", help="the GUI's API socket (default: %s)" % benchpilot.default_socket_path())
    ap.add_argument("--recipe", required=True, help="the dispensing recipe (*.recipe.json)")
    ap.add_argument("--calibration", default="none", help="slot calibration file, or none for the nominal deck")
    ap.add_argument("--roi", default="40,40,43,42", help="the scan's region, x0,y0,x1,y1 mm")
    ap.add_argument("--fov", default="1.33,1.33", help="camera field at the sample, w,h mm")
    ap.add_argument("--overlap", type=float, default=0.1)
    ap.add_argument("--out", default="plate-then-scan", help="folder for the run log and the scan")
    args = ap.parse_args()

    os.makedirs(args.out, exist_ok=True)
    log = os.path.join(args.out, "plate.run.jsonl")
    with benchpilot.connect(args.socket, name="plate-then-image") as bp, bp.acquire() as lease:
        # 1. The plate: one progress object per well as it is done, then the run's end.
        def well(p):
            if p.get("event") == "done":
                print("well %s (%d/%d), ETA %.0f s" % (p.get("well", "-"), p["ops_done"], p["ops"], p["eta_s"]), flush=True)
        end = bp.call("recipe.run", instrument="analyzer", file=args.recipe, calibration=args.calibration,
                      log=log, home=True, progress=well)
        print("plate: %s, %d of %d ops in %.0f s" % (end["event"], end["ops_done"], end["ops"], end["elapsed_s"]))
        if lease.lost.is_set():
            sys.exit("the operator took control back: stopping here")

        # 2. The scan: plan it (the same plan benchpilot-cli scan plan prints), save it, run it.
        plan = bp.call("scan.plan", roi=[float(v) for v in args.roi.split(",")],
                       fov=[float(v) for v in args.fov.split(",")], overlap=[args.overlap], format="json")
        plan_path = os.path.join(args.out, "slide.scan.json")
        with open(plan_path, "w") as f:
            json.dump(plan, f, indent=2)
        summary = bp.call("scan.plan", plan=plan_path, format="summary")
        print("scan: %d tiles, about %.0f s" % (summary["tiles"], summary["estimate_s"]))
        result = bp.call("scan.run", instrument="stage", plan=plan_path, out=os.path.join(args.out, "scan"), home=True, yes=True,
                         progress=lambda t: print("tile %d at %s" % (t["tile"], t["measured_mm"]), flush=True))
        print(result.get("text", result))


if __name__ == "__main__":
    main()
