"""The module pip installed into this venv: its place, its version, and a run of an example case.

    v/bin/python installed_module.py VERSION CASE CLI_SUMMARY_JSON BUILD_TYPE

VERSION is CMake's PROJECT_VERSION; CLI_SUMMARY_JSON the summary.json of `vibroimpact simulate CASE`
in the build folder. The same library at the same optimisation (a Release build folder; pip builds
Release) gives the same summary to the last bit; another build type is compared on its impacts.
"""

import importlib.metadata
import json
import pathlib
import sys

version, case_file, cli_summary, build_type = sys.argv[1:5]

import vibroimpact as vi  # noqa: E402

where = pathlib.Path(vi.__file__).resolve()
venv = pathlib.Path(sys.prefix).resolve()
assert venv in where.parents, f"vibroimpact imported from {where}, not from the venv {venv}"
installed = importlib.metadata.version("vibroimpact")
assert installed == version, f"installed version {installed}, CMake's project VERSION {version}"
assert vi.__version__ == version, f"vibroimpact.__version__ {vi.__version__}, CMake's project VERSION {version}"

run = vi.simulate(vi.Case.from_file(case_file))
cli = json.loads(pathlib.Path(cli_summary).read_text())
if build_type == "Release":
    assert run["summary"] == cli, "the installed module's summary differs from the command's"
else:
    assert len(run["summary"]["impacts"]) == len(cli["impacts"]), "impact counts differ from the command's"
impacts = len(run["summary"]["impacts"])
assert impacts > 0 and len(run["history"]["t_s"]) > 100, "the example case ran without impacts or history"
print(f"vibroimpact {installed} from {where.parent}: {impacts} impacts, T = {run['summary']['T_s']:.6g} s, "
      f"as the command ({build_type})")
