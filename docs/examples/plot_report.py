"""
The report of an analysis
=========================

``contact.write_report`` turns an analysis into one self-contained HTML page: the
verdict, the tables ``ltca run`` prints, the machine-settings sheet and every figure
(``ltca report FILE`` does the same from a file). Here the report of a quick analysis at
two torques, and the transmission-error figure it holds.
"""

from pathlib import Path

import contact

options = contact.LTCAOptions(rolls_per_cycle=8, segments=12)
tree = contact.run_analysis(None, [50.0, 250.0], options=options, root_stress=False)
page = contact.write_report(tree, Path("report.html"))
print(f"{page.name}: {page.stat().st_size / 1e6:.1f} MB, "
      f"verdict {contact.verdict(tree).severity}")
te = contact.transmission_error_figure(tree["utca"].to_dataset(), tree["ltca"].to_dataset())
page.unlink()
