-- Stand-in base scenario of the study-loading tests (only its existence is checked).
run { distance = 1 }
