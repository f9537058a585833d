"""Model fitting: seed 000 (clamping pressure) and seed 001 (Hammerstein grey box)."""
