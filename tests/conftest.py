import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "solutions"))  # coursekit, as the notebooks import it
os.environ.setdefault("MPLBACKEND", "Agg")
