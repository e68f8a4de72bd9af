"""Mechanical power loss and efficiency (seed chapter 5).

Lubricant properties, film thickness and lambda ratio, friction coefficient
models, rolling loss, power loss and efficiency.
"""
