"""Diagnosis: residuals of the fitted baseline, the effect catalogue, model comparison on held-out records."""
