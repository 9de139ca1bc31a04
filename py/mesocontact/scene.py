"""What every scene builder of this package shares (inside ``yade``)."""
from yade import O


def reset():
    """O.reset() keeping O.tags: yade-batch puts a job's description and parameters there, and a
    builder that wipes them makes the job fail (KeyError: 'Invalid key: description.')."""
    tags = {k: O.tags[k] for k in O.tags.keys()}
    O.reset()
    for k, v in tags.items():
        O.tags[k] = v
