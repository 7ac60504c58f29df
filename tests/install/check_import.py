"""Imports the installed coldblast from wherever it is run (not the source tree) and checks that it is
the package under SITE, built for this interpreter, that its __version__ is VERSION with the commit
(and, given, the CLI's COMMIT; installed by pip, its metadata's version), and that one call computes
the exact TvNS amplitude A_2 of the README (0.351935906848599, error 2.5e-14).

    python check_import.py SITE VERSION [COMMIT] [--pip]
"""
import importlib.metadata
import os
import re
import sys
import sysconfig

site, version = os.path.realpath(sys.argv[1]), sys.argv[2]
commit = sys.argv[3] if len(sys.argv) > 3 and sys.argv[3] != "--pip" else None
assert not os.path.exists(os.path.join(os.getcwd(), "coldblast")), "run from a folder without a coldblast/ in it"

import coldblast  # noqa: E402

package = os.path.dirname(os.path.realpath(coldblast.__file__))
assert package == os.path.join(site, "coldblast"), f"imported {package}, not the one in {site}"
extension = os.path.realpath(coldblast._coldblast.__file__)
assert extension == os.path.join(package, "_coldblast" + sysconfig.get_config_var("EXT_SUFFIX")), \
    f"{extension} is not built for {sys.executable}"

assert re.fullmatch(r"[0-9a-f]{12}(-dirty)?|unknown", coldblast.__commit__), coldblast.__commit__
assert coldblast.__version__ == f"{version}+{coldblast.__commit__.replace('-', '.')}", coldblast.__version__
if commit is not None:
    assert coldblast.__commit__ == commit, f"coldblast.__commit__ = {coldblast.__commit__}, the CLI's {commit}"
if "--pip" in sys.argv:
    assert importlib.metadata.version("coldblast") == coldblast.__version__, importlib.metadata.version("coldblast")

A = coldblast.tvns(d=2).A
assert abs(A - 0.351935906848599) < 1e-13, A
print(f"coldblast {coldblast.__version__} from {package}: A_2 = {A!r}")
