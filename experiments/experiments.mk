figures:
