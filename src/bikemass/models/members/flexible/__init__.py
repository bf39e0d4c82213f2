"""The flexible member of the model family."""
