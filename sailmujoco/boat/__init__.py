"""The boat as built: its parameters (frozen dataclasses, SI), the registered boats and boat files,
the hull's geometry, the MJCF model, its stability and the designer's check."""
