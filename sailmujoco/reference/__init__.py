"""The papers' own reduced models ("paper worlds"), integrated with scipy."""
