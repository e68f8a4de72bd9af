"""The seed's friction study (§5.2.3, issue 34): the mixed-EHL line-contact solver over
Table 5.1's contact conditions, and the fit of a μ formula to its results.

Modules
-------
design     the condition designs: Table 5.1's full factorial, space-filling (Sobol, LHS)
points     one design point solved by :mod:`friction.ehl` (status and reason kept)
fit        the regression of the ``kolivand2009`` model to a study's results

The runner on Dask (streaming, resume) is :mod:`contact.study.friction_study` (the
application layer), the command ``ltca friction-study``.
"""
