"""Public checks, one module per lesson (``lesson01.py``, ``lesson02.py``, ...).

Importing this package imports every lesson module, and each registers its
checks with :func:`coursekit.checking.public_check`.
"""

import importlib
import pkgutil

IMPORT_ERRORS = {}

for _module in pkgutil.iter_modules(__path__):
    if _module.name.startswith("lesson"):
        try:
            importlib.import_module(f"{__name__}.{_module.name}")
        except Exception as error:  # one broken lesson module must not break the others
            IMPORT_ERRORS[_module.name] = f"{type(error).__name__}: {error}"
