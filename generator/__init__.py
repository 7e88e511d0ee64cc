"""The ilahrs generator: spec/ilahrs.yaml -> load -> validate -> model -> layout -> render."""

from __future__ import annotations

from pathlib import Path

from . import layout as _layout
from . import load as _load
from . import model as _model
from . import validate as _validate
from .model import Spec

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_SPEC = ROOT / "spec" / "ilahrs.yaml"


def build_spec(path: Path = DEFAULT_SPEC) -> Spec:
    """Load, validate, model and lay out a spec; raise load.SpecError if it is unusable."""
    path = path.resolve()
    try:
        display = path.relative_to(ROOT).as_posix()
    except ValueError:
        display = path.name
    loaded = _load.load(path, display)
    _validate.validate(loaded)
    return _layout.layout(_model.build(loaded), loaded)
