"""Analysis layer: stochastic analysis, overturning spectra, Monte Carlo and fragility.

Built on the model interface (:func:`rocking.simulate`, :func:`rocking.simulate_many`);
every function returns a tidy :class:`pandas.DataFrame` or a result object with a
``plot()``.
"""
