"""The members of the model family, one package each."""
