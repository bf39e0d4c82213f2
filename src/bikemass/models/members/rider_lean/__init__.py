"""The rider_lean member of the model family."""
