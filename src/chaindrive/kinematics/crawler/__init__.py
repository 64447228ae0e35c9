r"""Crawler (caterpillar) drive unit of a conveyor (the crawler drive text).

A *drive chain* carrying cams runs round a driving and a tensioning sprocket with the same
tooth count, turning in phase; the cams engage the hinges of the conveyor's traction chain.

* :mod:`.laws` - displacement, velocity and acceleration of the drive chain without a
  guide (eq. 6.7) and with the tangent guide (eqs 6.14-6.16);
* :mod:`.cam` - the elastic drive chain: the force on the cam (rebuilt) and the guide
  reaction (the text's "pushing-off forces");
* :mod:`.drive` - :func:`crawler_drive` over one tooth period, the speed non-uniformity.

See ``docs/crawler.md``.
"""

from . import laws as _laws
from .cam import (
    ElasticLoop,
    cam_force,
    cam_hinge_distance,
    cam_pushing_off_force,
    cam_stiffness,
    elastic_loop,
    guide_reaction,
)
from .drive import MEASURES, SUMMARY_KEYS, CrawlerKinematics, crawler_drive, crawler_nonuniformity
from .laws import *  # noqa: F403 - the motion laws, named once in laws.__all__

__all__ = [
    "MEASURES",
    "SUMMARY_KEYS",
    "CrawlerKinematics",
    "ElasticLoop",
    "cam_force",
    "cam_hinge_distance",
    "cam_pushing_off_force",
    "cam_stiffness",
    "crawler_drive",
    "crawler_nonuniformity",
    "elastic_loop",
    "guide_reaction",
    *_laws.__all__,
]
