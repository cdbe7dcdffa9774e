"""numpy, imported on first use: ``import jacobs_ladder`` stays fast (numpy
alone takes about 120 ms to import); the first array made loads it."""

from typing import Any


class _LazyNumpy:
    def __getattr__(self, name: str) -> Any:
        import numpy

        return getattr(numpy, name)


np: Any = _LazyNumpy()
