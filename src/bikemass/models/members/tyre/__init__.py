"""The tyre member of the model family."""
