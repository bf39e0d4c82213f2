"""The arms member of the model family."""
