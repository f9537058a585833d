"""Simulated instruments on real transports, all driven by one simulated bench (the "world").

May import labrig.physics (the world is physics) and nothing else of labrig.
"""
