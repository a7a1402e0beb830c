"""prox: exact proximity queries between MCNP macrobodies (RCC, BOX, RPP, SPH, TRC, REC, ELL,
RHP/HEX, WED, ARB).

    import prox, numpy as np
    a = prox.RCC([0, 0, 0], [0, 0, 5], 2)
    b = prox.SPH(np.random.rand(1000, 3) * 20, 1.5)
    r = prox.distance(a, b)          # r.distance (1000,), r.p1, r.p2, r.intersect, r.status ...

Every query answers a batch in C with the GIL released, on all cores by default. See docs/python.md.
"""

from . import _prox
from ._query import (
    DistanceResult,
    ProxError,
    SignedResult,
    TestResult,
    check_deck,
    distance,
    query,
    signed_distance,
    status_str,
    test,
)
from ._shapes import ARB, BOX, ELL, HEX, RCC, REC, RHP, RPP, SPH, TRC, WED

__version__ = _prox.version()

# The prox_status codes of status.h: STATUS_OK == 0, STATUS_EINVAL_RADIUS, ...
globals().update({k: getattr(_prox, k) for k in dir(_prox) if k.startswith("STATUS_")})

__all__ = [
    "RCC", "BOX", "RPP", "SPH", "TRC", "REC", "ELL", "RHP", "HEX", "WED", "ARB",
    "distance", "signed_distance", "test", "query", "check_deck", "status_str",
    "DistanceResult", "SignedResult", "TestResult", "ProxError",
    "__version__",
]
