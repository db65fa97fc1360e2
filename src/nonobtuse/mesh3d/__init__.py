from nonobtuse.mesh3d.gabriel import Gabriel3DResult, GabrielReport, check_gabriel, refine_gabriel
