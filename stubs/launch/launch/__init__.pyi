# launch/launch/__init__.py: `from . import actions` (ExecuteProcess is imported from launch.actions)
