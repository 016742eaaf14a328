"""HTTP service for the PMA calculator: translates JSON to :mod:`pma_core` and back."""
