"""Sub-commands of ``ltca``, one module each, registered in :data:`contact.cli.COMMANDS`."""
