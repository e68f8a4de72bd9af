"""Bundled gear-pair cases (TOML), installed as the package data ``contact.cases``."""
