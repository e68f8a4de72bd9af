"""The toolkit-wide low layer: what every package may import, with no gear in it.

errors         the exception family (:class:`LTCAError` and its children)
validation     checks of scalar and array inputs that name the field and its range
conventions    the dataset conventions (units, long names)
io             netCDF files of the toolkit: conventions, atomic writes, reading
atomic_files   write to a temporary file, then rename
toml_files     TOML input files read and written
hertz          Hertz line contact and the contact modulus
version        the toolkit's version
caches         the per-process memos, all cleared by clear_caches
registries     what the registries of interchangeable models share (names, signatures,
               plug-ins)
bisection      the largest argument at which a trial still succeeds
"""
