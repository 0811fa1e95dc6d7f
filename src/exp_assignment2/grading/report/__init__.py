"""Report: a grading's pages (no ROS): the index, one page per submission and
report.json (:mod:`.index`; the teacher's pages :mod:`.pages`, with their
sections :mod:`.camera`,
:mod:`.failures`, :mod:`.judged`, :mod:`.packages`, :mod:`.releases`,
:mod:`.starts`, :mod:`.figures`), the marks and grades.csv (:mod:`.marks`),
the students' own pages (:mod:`.feedback`) and Gradescope's files
(:mod:`.gradescope`); every page's HTML helpers in one place (:mod:`.html`)."""
