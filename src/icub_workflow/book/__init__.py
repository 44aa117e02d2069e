"""What the book says: each page's values and tables (``pages``), the scorecard, and the verdict
words and phrases a test chooses (``text``); the sentences are ``book/*.md``'s."""
