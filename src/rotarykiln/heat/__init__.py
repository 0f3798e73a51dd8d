"""Heat-transfer closures for rotary kilns: convection, contact, radiation, wall and shell.

Pure functions of SI floats or arrays, each named after its model and author. The assembled
kiln model (``rotarykiln.kiln``) picks them by name.
"""
