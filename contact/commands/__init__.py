"""Sub-commands of ``ltca``, one module each with ``register(subparsers)`` and ``ORDER``."""
