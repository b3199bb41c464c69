"""What a designer asks of a boat: its check (displacement, stability, periods, speeds) and its speed
polar, both run on the sweep engine."""
