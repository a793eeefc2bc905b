"""The one exception of the report library."""


class ReportError(Exception):
    """A report cannot be written from the files it was given: the message names the file (and
    the line, card, field or array) and what is wrong. Report scripts let it end the script with
    that message and a non-zero exit (see `sigreport.main_guard`)."""
