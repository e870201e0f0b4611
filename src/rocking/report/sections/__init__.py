"""The report's sections, one module per table or figure of the paper (or group of them).

Each module registers its sections with :func:`rocking.report.core.section` when it is
imported; :mod:`rocking.report` imports the modules listed in
:data:`rocking.report.SECTION_MODULES`.
"""
