"""Support code for the course "Rotations, hands on".

- :func:`check` runs the public checks of an exercise (the check cells).
- :func:`ready_to_hand_in` runs a whole lesson's public checks at once (its last cell).
- :func:`show` prints values the same way on every machine.
- :mod:`coursekit.plotting` draws frames, points and axes (imports matplotlib).
- :mod:`coursekit.diagnose` names likely mistakes; the grader uses it too.
- :mod:`coursekit.stubs`: in a notebook, a cell that reaches an unwritten exercise ends in one line
  naming it (installed when coursekit is imported).
"""

from .checking import check
from .display import show
from .edition import install_caption_metadata
from .handin import ready_to_hand_in
from .stubs import install_stub_handler

install_stub_handler()
install_caption_metadata()

__all__ = ["check", "show", "ready_to_hand_in"]
