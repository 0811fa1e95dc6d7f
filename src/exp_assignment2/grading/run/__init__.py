"""Run: one run of a submission in its sandbox, here or on a Dask worker: the
sandbox (:mod:`.sandbox`), its display and windows (:mod:`.display`,
:mod:`.windows`), the driver inside it (:mod:`.inside`), the ground truth
outside it (:mod:`.truth`, :mod:`.peer`), the run, its monitor and why it
ends (:mod:`.runner`, :mod:`.monitor`, :mod:`.ending`, :mod:`.files`,
:mod:`.cpu`), and the run as a task that travels, sent and received
(:mod:`.tasks`, :mod:`.cluster`, :mod:`.dispatch`, :mod:`.worker`)."""
