"""Similarity: the code submissions share, for a person to read (no ROS):
fingerprints and pairs (:mod:`.fingerprints`), the page (:mod:`.page`) and
the grading's step that makes them (:mod:`.step`)."""
