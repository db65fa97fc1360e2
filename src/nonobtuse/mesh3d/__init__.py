# Exact Gabriel certificate and Ruppert-like refinement (helper gabriel3d)
from nonobtuse.mesh3d.gabriel import Gabriel3DResult as Gabriel3DResult
from nonobtuse.mesh3d.gabriel import GabrielReport as GabrielReport
from nonobtuse.mesh3d.gabriel import check_gabriel as check_gabriel
from nonobtuse.mesh3d.gabriel import refine_gabriel as refine_gabriel
