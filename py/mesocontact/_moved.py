"""The old import paths of modules that moved into subpackages, kept for scripts and users:
``from mesocontact import campaign`` and ``python3 -m mesocontact.statements`` give the moved
module itself (one module object, one state), not a copy."""
import importlib
import importlib.abc
import importlib.util
import sys

MOVED = {name: "tablet." + name for name in
         ("campaign", "stages", "uniaxial", "snapshots", "measures", "statements", "branchplot")}


class _Finder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    def __init__(self, package):
        self.prefix = package + "."

    def _target(self, fullname):
        if not fullname.startswith(self.prefix):
            return None
        head, dot, rest = fullname[len(self.prefix):].partition(".")
        new = MOVED.get(head)
        return new and self.prefix + new + dot + rest

    def find_spec(self, fullname, path=None, target=None):
        if self._target(fullname):
            return importlib.util.spec_from_loader(fullname, self)
        return None

    def create_module(self, spec):
        return None

    def exec_module(self, module):
        # the import system returns what sys.modules holds under the name after this call
        sys.modules[module.__name__] = importlib.import_module(self._target(module.__name__))

    def get_code(self, fullname):  # python3 -m <old path>: run the moved module as __main__
        return compile(f"import runpy; runpy.run_module({self._target(fullname)!r}, run_name='__main__')",
                       f"<{fullname}>", "exec")


def install(package):
    if not any(isinstance(f, _Finder) for f in sys.meta_path):
        sys.meta_path.insert(0, _Finder(package))
