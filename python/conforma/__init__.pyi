"""Type stubs of the public API of conforma (python/conforma/__init__.py)."""
import pathlib
from typing import Any, Dict, List, Optional, Union

from . import types as types
from . import _core
from ._core import InputError as InputError
from ._core import Profile as Profile
from ._core import Track as Track
from ._core import check_scenario as check_scenario
from ._core import default_shared_data as default_shared_data
from ._core import has_wear as has_wear
from ._core import load_profile as load_profile
from ._core import load_scenario as load_scenario
from ._core import profile_from_points as profile_from_points
from ._core import rail as rail
from ._core import s1002 as s1002
from ._core import wheel_dimensions as wheel_dimensions
from ._campaign import CampaignError as CampaignError
from ._campaign import campaign as campaign
from ._campaign import campaign_report as campaign_report
from ._grid import patch_grid as patch_grid
from ._status import IncompleteResultError as IncompleteResultError
from ._status import IncompleteResultWarning as IncompleteResultWarning
from ._status import wear_problems as wear_problems
from ._status import wheel_problems as wheel_problems
from .types import ManchesterRow, WearRun, Wheel

class ContactLut(_core.ContactLut):
    def evaluate(self, track: Track, side: str, lateral_m: float, yaw_rad: float = 0.0, load_N: float = 50000.0,
                 speed_m_s: float = 2.0, lateral_velocity_m_s: float = 0.0, yaw_rate_rad_s: float = 0.0,
                 axle_angular_velocity_rad_s: Optional[float] = None, mu: float = 0.3, grid: int = 30,
                 load_balance: str = "total", creep_force: str = "fastsim", *, strict: bool = False) -> Wheel: ...

__version__: str
__all__: List[str]

def contact(track: Track, lateral_m: float = 0.0, yaw_rad: float = 0.0, roll_rad: Optional[float] = None,
            model: str = "hertz", load_N: float = 10000.0, speed_m_s: float = 2.0, mu: float = 0.3,
            shear_modulus_Pa: float = 82000000000.0, poisson_ratio: float = 0.28, grid: int = 30,
            approach_m: float = 5e-05, side: str = "both", xi: Optional[float] = None, eta: Optional[float] = None,
            phi_per_m: Optional[float] = None, fields: bool = True, exact_element_m: float = 0.0002, *,
            strict: bool = False) -> List[Wheel]: ...
def contact_at_pose(track: Track, side: str, lateral_m: float, vertical_m: float, roll_rad: float = 0.0,
                    yaw_rad: float = 0.0, speed_m_s: float = 2.0, lateral_velocity_m_s: float = 0.0,
                    yaw_rate_rad_s: float = 0.0, axle_angular_velocity_rad_s: Optional[float] = None,
                    model: str = "hertz", load_N: float = -1.0, mu: float = 0.3,
                    shear_modulus_Pa: float = 82000000000.0, poisson_ratio: float = 0.28, grid: int = 30,
                    fields: bool = True, exact_element_m: float = 0.0002, *, strict: bool = False) -> Wheel: ...
def manchester(model: str = "conformal", creepages_from_file: bool = True, data_dir: str = ...,
               fastsim_elements: int = 30, *, strict: bool = False) -> List[ManchesterRow]: ...
def wear(scenario: Union[str, Dict[str, Any]], model: str = "", steps: int = -1, total_km: float = -1.0,
         base_dir: str = ".", *, strict: bool = False) -> WearRun: ...
def share_dir() -> pathlib.Path: ...
def scenario_path(name: str = "default_metro") -> str: ...
