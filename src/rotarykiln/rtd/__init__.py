"""Residence time distribution and axial dispersion of the solids (seed 003, Bongo Njeng 2015).

Modules: ``tracer`` (tracer curves -> E(t), moments, replicate statistics), ``dispersion`` (RTD
models), ``dispersion_pde`` (numerical dispersion equation), ``fitting`` (moment method, least
squares), ``correlations`` (Sai, Sherritt, Bongo Njeng), ``internals`` (lifters, exit dams),
``predict`` (E(t) of a case), ``plots`` (parity plots). See docs/rtd.md.
"""
