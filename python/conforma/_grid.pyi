from typing import Mapping

from .types import Grid

def patch_grid(fields: Mapping[str, object]) -> Grid: ...
