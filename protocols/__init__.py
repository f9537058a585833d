"""The experiments as code (plans that yield steps) and their TOML presets."""
