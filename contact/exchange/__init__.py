"""Exchange with other tools: REXS bevel stages (:mod:`contact.exchange.rexs`)."""
