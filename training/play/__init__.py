"""A person in the human seat: one play session and two front ends (browser, terminal).

:mod:`.session` holds the environment and the robot and records the game as a trace;
:mod:`.web` serves it as a local web page, :mod:`.tui` in a terminal; :mod:`.svg`
draws the table for the page; :mod:`.stats` summarises recorded traces.
"""
