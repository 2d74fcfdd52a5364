"""The user's question answered: force, contact size and pressure for a layer and a punch.

This group sits above the asymptotic stages and the direct solvers and is the only one, besides the
validation studies, that uses both: it chooses the model that holds to the requested tolerance.
"""
